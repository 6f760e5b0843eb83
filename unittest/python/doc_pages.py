"""Reading the manual's pages (doc/*.rst) and the parsers' keyword tables (src/style_keywords.h)
for the documentation tests: sections by their headings, bold run-in titles, the
cross-references a page makes to a section ("see X", "X" below, page.rst "X")."""
import os
import re
from pathlib import Path

TOP = Path(__file__).resolve().parents[2]
DOC = TOP / "doc"
UNIT_STYLES = ("si", "metal", "real", "cgs", "lj")
# the sections of a LAMMPS command page, in order
COMMAND_SECTIONS = ("Syntax", "Examples", "Description", "Restrictions", "Related commands",
                    "Default")

_UNDERLINE = re.compile(r'^([=\-"~^*#+`\':.])\1{2,}\s*$')


def lammps_source():
    """The LAMMPS source tree the plugin was built against (build/CMakeCache.txt)."""
    given = os.environ.get("LAMMPS_SOURCE")
    if given:
        return Path(given)
    build = Path(os.environ.get("CLUSTERDYN_BUILD_DIR", TOP / "build"))
    m = re.search(r"^LAMMPS_ROOT:\w+=(.*)$", (build / "CMakeCache.txt").read_text(), re.M)
    return Path(m.group(1))


def keyword_tables(header=TOP / "src" / "style_keywords.h"):
    """{table name: (doc page, [(keyword, values, dimension, use), ...])} as the parsers take
    them (one entry a line after a '// doc: PAGE' comment)."""
    tables, page, name = {}, None, None
    entry = re.compile(r'\{"([^"]+)",\s*(-?\d+),\s*"([^"]*)",\s*(OPTIONAL|REQUIRED)\}')
    for line in header.read_text().splitlines():
        m = re.match(r"\s*// doc: (\w+)", line)
        if m:
            page = m.group(1)
            continue
        m = re.match(r"\s*inline const KeywordTable (\w+) = \{", line)
        if m:
            name = m.group(1)
            tables[name] = (page, [])
            continue
        m = entry.search(line)
        if m and name:
            tables[name][1].append((m.group(1), int(m.group(2)), m.group(3), m.group(4)))
        if line.strip() == "};":
            name = None
    return tables


class Page:
    """One .rst page: its headings (title, line index) and the text under each."""

    def __init__(self, path):
        self.path = Path(path)
        self.lines = self.path.read_text().splitlines()
        self.headings = []
        for k in range(1, len(self.lines)):
            title = self.lines[k - 1].strip()
            if (title and _UNDERLINE.match(self.lines[k])
                    and not _UNDERLINE.match(self.lines[k - 1])
                    and len(self.lines[k].rstrip()) >= len(title)):
                self.headings.append((title, k - 1))

    @property
    def text(self):
        return "\n".join(self.lines)

    def titles(self):
        return [t for t, _ in self.headings]

    def section(self, title):
        """The text under the first heading named title, up to the next heading; else the
        paragraphs of a bold run-in title (**Title.** ...) up to the next bold run-in title or
        heading; None if the page has neither."""
        for n, (t, k) in enumerate(self.headings):
            if t == title:
                end = self.headings[n + 1][1] if n + 1 < len(self.headings) else len(self.lines)
                return "\n".join(self.lines[k + 2:end])
        starts = {k for _, k in self.headings}
        for k, line in enumerate(self.lines):
            if line.startswith(f"**{title}.**") or line.startswith(f"**{title}**"):
                end = k + 1
                while (end < len(self.lines) and end not in starts
                       and not re.match(r"\*\*[^*]+\*\*", self.lines[end])):
                    end += 1
                return "\n".join(self.lines[k:end])
        return None

    def names(self):
        """What a reference may name: headings (with and without a closing parenthesis) and
        bold run-in titles (**Title.** ...)."""
        found = set()
        for t in self.titles():
            found.add(t)
            found.add(re.sub(r"\s*\(.*\)$", "", t))
        for m in re.finditer(r"\*\*([^*]+?)\.?\*\*", self.text):
            found.add(m.group(1).strip())
        return found


# "X" below / "X" above / see "X", with an optional page named just before it
_REF = re.compile(r'(?:[Ss]ee\s+)?"([A-Z][^"\n]{2,80}?)"\s*(below|above)?')
_PAGE_BEFORE = re.compile(r'(?:(\w+)\.rst|:doc:`(?:[^`<]*<)?(\w+)>?`)[^"\n.;]{0,30}$')


def section_references(path):
    """[(line number, page name or None for this page, section name)] of a page's references
    to sections: a quoted capitalised name after 'see' or before 'below'/'above', or right
    after a page name (page.rst "X", :doc:`page` "X")."""
    refs = []
    text = Path(path).read_text()
    for m in _REF.finditer(text):
        before = text[max(0, m.start() - 60):m.start()]
        page = _PAGE_BEFORE.search(before)
        target = (page.group(1) or page.group(2)) if page else None
        is_ref = target is not None or m.group(2) or m.group(0).lower().startswith("see")
        if is_ref:
            line = text.count("\n", 0, m.start()) + 1
            refs.append((line, target, m.group(1)))
    return refs
