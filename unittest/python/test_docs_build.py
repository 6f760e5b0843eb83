"""The manual builds as LAMMPS builds its own: tools/build_docs.sh runs sphinx-build -W (every
warning an error) over doc/, and a :doc: link to a LAMMPS page must name a page of the LAMMPS
source tree the plugin is built against (doc/conf.py)."""
import os
import shutil
import subprocess

from doc_pages import DOC, TOP, lammps_source

BUILD = TOP / "tools" / "build_docs.sh"


def build(doc, out):
    env = dict(os.environ, LAMMPS_SOURCE=str(lammps_source()))
    return subprocess.run(["sphinx-build", "-b", "html", "-W", "--keep-going", "-q", "-E",
                           str(doc), str(out)], env=env, capture_output=True, text=True,
                          timeout=300)


def test_build_script_builds_every_page(tmp_path):
    env = dict(os.environ, LAMMPS_SOURCE=str(lammps_source()))
    out = subprocess.run(["bash", str(BUILD), str(tmp_path / "html")], env=env,
                         capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stdout + out.stderr
    for page in DOC.glob("*.rst"):
        assert (tmp_path / "html" / f"{page.stem}.html").is_file(), page.name
    # a LAMMPS page is linked to LAMMPS's manual, an own page stays internal
    dust = (tmp_path / "html" / "compute_dust.html").read_text()
    assert 'href="https://docs.lammps.org/compute_cluster_atom.html"' in dust
    assert 'href="pair_spline.html"' in dust


def copy_of_doc(tmp_path, page, old, new):
    doc = tmp_path / "doc"
    shutil.copytree(DOC, doc)
    text = (doc / page).read_text()
    assert old in text
    (doc / page).write_text(text.replace(old, new, 1))
    return doc


def test_a_lammps_page_that_does_not_exist_fails(tmp_path):
    doc = copy_of_doc(tmp_path, "compute_dust.rst", ":doc:`compute cluster/atom <compute_cluster_atom>`",
                      ":doc:`compute cluster/atom <fix_neigh_history>`")
    out = build(doc, tmp_path / "html")
    assert out.returncode != 0
    assert "unknown document: 'fix_neigh_history'" in out.stderr


def test_a_broken_section_underline_fails(tmp_path):
    doc = copy_of_doc(tmp_path, "compute_dust.rst", 'Syntax\n""""""', 'Syntax\n"""""')
    out = build(doc, tmp_path / "html")
    assert out.returncode != 0
    assert "Title underline too short" in out.stderr
