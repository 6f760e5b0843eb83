# Sphinx configuration of the plugin's manual, built as LAMMPS builds its own
# (tools/build_docs.sh: sphinx-build -W, every warning an error).
#
# LAMMPS's pages: a :doc:`name` that is not a page of this folder links to
# LAMMPS's online manual (https://docs.lammps.org/name.html), and must name a page
# of the LAMMPS source tree the plugin is built against (its doc/src/name.rst):
# a name LAMMPS does not have stays an unknown document, a warning, so an error
# under -W.  The tree is LAMMPS_SOURCE, else the one build/CMakeCache.txt names
# (LAMMPS_ROOT); its doc/utils/sphinx-config/LAMMPSLexer.py highlights the
# ``code-block:: LAMMPS`` inputs.  Without a tree the LAMMPS links are not
# checked and the inputs are shown as plain text.
import os
import re
import sys
from pathlib import Path

from docutils import nodes

project = "Cluster-dynamics plugin for LAMMPS"
author = "the cluster-dynamics plugin developers"
copyright = "the cluster-dynamics plugin developers; GPL-2.0, as LAMMPS"
root_doc = "index"
exclude_patterns = ["_build", "benchmarks"]
extensions = ["sphinx.ext.mathjax"]
html_theme = "classic"
html_static_path = []
highlight_language = "none"

LAMMPS_MANUAL = "https://docs.lammps.org"
here = Path(__file__).resolve().parent


def lammps_source():
    given = os.environ.get("LAMMPS_SOURCE")
    if given:
        return Path(given)
    cache = here.parent / "build" / "CMakeCache.txt"
    if cache.is_file():
        m = re.search(r"^LAMMPS_ROOT:\w+=(.*)$", cache.read_text(), re.M)
        if m:
            return Path(m.group(1))
    return None


source = lammps_source()
lammps_pages = None
if source is not None:
    pages = source / "doc" / "src"
    if not pages.is_dir():
        sys.exit(f"conf.py: no LAMMPS doc/src in {source} (LAMMPS_SOURCE or build/CMakeCache.txt)")
    lammps_pages = {p.stem for p in pages.glob("*.rst")}
    sys.path.insert(0, str(source / "doc" / "utils" / "sphinx-config"))
    import LAMMPSLexer  # noqa: E402
    from sphinx.highlighting import lexers  # noqa: E402
    lexers["LAMMPS"] = LAMMPSLexer.LAMMPSLexer(startinline=True)


def lammps_page(app, env, node, contnode):
    """A :doc: reference that is not ours: LAMMPS's page of that name, if it has one."""
    if node.get("reftype") != "doc":
        return None
    target = node["reftarget"]
    if lammps_pages is not None and target not in lammps_pages:
        return None
    link = nodes.reference("", "", internal=False, refuri=f"{LAMMPS_MANUAL}/{target}.html")
    link.append(contnode)
    return link


def setup(app):
    if source is None:
        from sphinx.highlighting import lexers
        from pygments.lexers.special import TextLexer
        lexers["LAMMPS"] = TextLexer()
    app.connect("missing-reference", lammps_page)
