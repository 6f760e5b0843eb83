"""Documentation coverage: every keyword a parser takes (the tables of src/style_keywords.h,
which the parsers check their input against and list in their errors) is on its command's page:
in Syntax (as *keyword*), a dimensioned one in the page's Units section for every unit style,
an optional one in Default; every command page has LAMMPS's sections in order; every reference
to a section by name ("see X", "X" below, page.rst "X") names one that exists."""
import re

import pytest

from conftest import SCENE_MORSE, lmp_error, scene_box, scene_mca
from doc_pages import (COMMAND_SECTIONS, DOC, TOP, UNIT_STYLES, Page, keyword_tables,
                       section_references)

TABLES = keyword_tables()
COMMAND_PAGES = sorted(p.stem for p in DOC.glob("*.rst") if ".. index::" in p.read_text())
REFERRING = sorted(DOC.glob("*.rst")) + sorted(TOP.glob("examples/*/*.md")) + [TOP / "README.md"]

MCA = scene_mca() + ["pair_style mca fraction 0.74048"]
# a command with an unknown keyword: its error lists the table the parser checks against
BOGUS = {
    "SPLINE_STYLE": scene_box() + ["pair_style morse/spline cut 1.3 zzbogus 1"],
    "SPLINE_COEFF": scene_box() + ["pair_style morse/spline cut 1.3",
                                   "pair_coeff * * 1.0 6.0 1.0 zzbogus 1"],
    "MCA_STYLE": scene_mca() + ["pair_style mca fraction 0.74048 zzbogus 1"],
    "MCA_MATERIAL": MCA + ["pair_coeff 1 1 bulk 1 shear 1 zzbogus 1"],
    "MCA_SEGMENTS": MCA + ["pair_coeff 1 2 segments 0.3 zzbogus 1"],
    "VISCOUS_RELATIVE": SCENE_MORSE + ["fix v all viscous/relative gamma 1.0 zzbogus 1"],
    "DESCENT_NORMALIZED": SCENE_MORSE + ["fix d all descent/normalized h 0.1 zzbogus 1"],
    "DUST": SCENE_MORSE + ["compute d all dust zzbogus 1"],
    "FREE_SURFACE": SCENE_MORSE + ["compute d all dust",
                                   "compute f all free/surface d 1.0 zzbogus 1"],
    "PAIR_PARAMS": SCENE_MORSE + ["compute p all pair/params 1 1 zzbogus 1"],
}
# read by position, not through a keyword set: pair_coeff I J link yes|no | segments ...
POSITIONAL = {"MCA_TYPES"}


def test_the_tables_are_read():
    assert set(TABLES) == set(BOGUS) | POSITIONAL
    for name, (page, entries) in TABLES.items():
        assert page and (DOC / f"{page}.rst").is_file(), name
        assert entries, name


@pytest.mark.parametrize("name", sorted(BOGUS))
def test_the_parser_takes_its_table(tmp_path, name):
    out = lmp_error(tmp_path, BOGUS[name])
    m = re.search(r"unknown keyword 'zzbogus' \(expected ([^)]*)\)", out)
    assert m, out[-2000:]
    names = [e[0] for e in TABLES[name][1]]
    assert m.group(1) == ", ".join(names[:-1]) + " or " + names[-1]    # "a, b or c"


CASES = [(name, entry) for name, (_, entries) in sorted(TABLES.items()) for entry in entries]


@pytest.mark.parametrize("name,entry", CASES, ids=[f"{n}-{e[0]}" for n, e in CASES])
def test_keyword_on_its_page(name, entry):
    keyword, _, dimension, use = entry
    page = Page(DOC / f"{TABLES[name][0]}.rst")
    syntax = page.section("Syntax")
    assert syntax is not None, f"{page.path.name} has no Syntax section"
    assert f"*{keyword}*" in syntax, f"{keyword} is not in {page.path.name}'s Syntax"
    word = re.compile(rf"(?<![\w-]){re.escape(keyword)}(?![\w-])")
    if dimension:
        units = page.section("Units")
        assert units is not None, f"{page.path.name} has no Units section ({keyword}: {dimension})"
        assert word.search(units), f"{keyword} ({dimension}) is not in {page.path.name}'s Units"
        for style in UNIT_STYLES:
            assert re.search(rf"\b{style}\b", units), f"{page.path.name}'s Units lacks {style}"
    if use == "OPTIONAL":
        default = page.section("Default")
        assert default is not None, f"{page.path.name} has no Default section"
        assert word.search(default), f"{keyword}'s default is not in {page.path.name}'s Default"


@pytest.mark.parametrize("name", COMMAND_PAGES)
def test_command_page_sections(name):
    titles = Page(DOC / f"{name}.rst").titles()
    missing = [s for s in COMMAND_SECTIONS if s not in titles]
    assert not missing, f"{name}.rst lacks {missing}"
    at = [titles.index(s) for s in COMMAND_SECTIONS]
    assert at == sorted(at), f"{name}.rst: sections out of LAMMPS's order {COMMAND_SECTIONS}"


@pytest.mark.parametrize("name", COMMAND_PAGES)
def test_command_page_says_its_units_in_every_unit_style(name):
    units = Page(DOC / f"{name}.rst").section("Units")
    assert units is not None, f"{name}.rst has no Units section or **Units.** paragraph"
    for style in UNIT_STYLES:
        assert re.search(rf"\b{style}\b", units), f"{name}.rst's Units lacks {style}"


@pytest.mark.parametrize("path", REFERRING, ids=[str(p.relative_to(TOP)) for p in REFERRING])
def test_section_references_exist(path):
    broken = []
    for line, target, title in section_references(path):
        if target is None and path.suffix != ".rst":
            continue    # a quotation in a README, not a reference to its own section
        page = path if target is None else DOC / f"{target}.rst"
        if not page.is_file():
            continue    # a LAMMPS page (the Sphinx build checks those)
        if title not in Page(page).names():
            broken.append(f"line {line}: \"{title}\" in {page.name}")
    assert not broken, f"{path.name}: references to sections that do not exist: {broken}"


def test_reference_reader_finds_a_broken_reference(tmp_path):
    """The reader is not blind: a reference to a missing section is found, an existing one not."""
    page = tmp_path / "p.rst"
    page.write_text('Title\n=====\n\nReal one\n""""""""\n\nSee "Real one" and "Lost one" below;'
                    ' pair_mca.rst "Shock equation of state".\n')
    refs = section_references(page)
    assert (7, None, "Lost one") in refs and (7, None, "Real one") in refs
    assert (7, "pair_mca", "Shock equation of state") in refs
    names = Page(page).names()
    assert "Real one" in names and "Lost one" not in names
