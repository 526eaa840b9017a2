# Sphinx configuration of the whirl documentation site (built by scripts/docs.sh into build/docs/html).
# Pages are MyST Markdown; the C++ API reference comes from Doxygen XML through Breathe. Every warning
# is an error (scripts/docs.sh passes -W --keep-going), so a broken cross-reference fails the build.
import os
import pathlib

project = "whirl"
author = "the whirl developers"
copyright = "the whirl developers"

extensions = ["myst_parser", "breathe", "sphinx.ext.autodoc", "sphinx.ext.napoleon"]

# The Python API reference (user/python-api.md) is read from the built module's docstrings: scripts/docs.sh
# puts BUILD/python on PYTHONPATH. Members in source order, as the docstrings refer to each other.
autodoc_member_order = "bysource"
autodoc_typehints = "description"
napoleon_numpy_docstring = True
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]

# Anchors for headings down to ####, so pages can link to [text](page.md#a-section).
myst_heading_anchors = 4
myst_enable_extensions = ["colon_fence", "deflist"]

# Doxygen XML written by scripts/docs.sh (WHIRL_DOXYGEN_XML); the API page needs it.
breathe_projects = {"whirl": os.environ.get("WHIRL_DOXYGEN_XML", "../build/docs/doxygen/xml")}
breathe_default_project = "whirl"
breathe_domain_by_extension = {"hpp": "cpp", "hxx": "cpp"}

html_theme = "alabaster"
html_title = "whirl"
html_static_path = []


# Pages in deeper folders (docs/user/openfast/elastodyn.md, …) join the tree by themselves too: a
# hidden toctree of them is appended to the index when it is read. (A glob such as `theory/*/*` in
# index.md would do it, but Sphinx warns for a glob that matches nothing, and warnings are errors.)
_SECTIONS = ("user", "theory", "dev")
_LISTED = ("user/commands",)  # folders the index lists with a glob of their own


def _deeper_pages(srcdir):
    root = pathlib.Path(srcdir)
    pages = []
    for section in _SECTIONS:
        for page in sorted((root / section).glob("*/**/*.md")):
            docname = page.relative_to(root).with_suffix("").as_posix()
            if not any(docname.startswith(folder + "/") and docname.count("/") == 2 for folder in _LISTED):
                pages.append(docname)
    return pages


def _append_deeper_pages(app, docname, source):
    if docname != root_doc:
        return
    pages = _deeper_pages(app.srcdir)
    if pages:
        source[0] += "\n\n```{toctree}\n:hidden:\n\n" + "\n".join(pages) + "\n```\n"


def setup(app):
    app.connect("source-read", _append_deeper_pages)
