"""Sphinx configuration of the rigidmech documentation.

Build with ``python -m sphinx -W --keep-going -b html docs docs/_build/html`` after
``python -m pip install -e ".[docs]"``. Nothing is fetched from the network at build time (no
intersphinx); MathJax is loaded by the reader's browser. The example gallery executes every
``examples/plot_*.py`` and aborts the build on the first error.
"""

import os
import sys
from importlib.metadata import PackageNotFoundError
from importlib.metadata import version as _dist_version
from pathlib import Path

os.environ.setdefault("MPLBACKEND", "Agg")
import matplotlib

matplotlib.use("Agg")

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "src"))  # document the tree even without an install

# -- Project --------------------------------------------------------------------------------
project = "rigidmech"
author = "the rigidmech developers"
copyright = "2025, the rigidmech developers"
try:
    release = _dist_version("rigidmech")
except PackageNotFoundError:  # building from a bare checkout
    release = "0.1.0"
version = ".".join(release.split(".")[:2])

# -- General --------------------------------------------------------------------------------
extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "numpydoc",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "sphinx_gallery.gen_gallery",
]
root_doc = "index"
exclude_patterns = ["_build", "Thumbs.db", ".DS_Store"]
default_role = "py:obj"  # `Torsor` in docstrings links to the object
pygments_style = "sphinx"

# -- autodoc / autosummary / numpydoc -------------------------------------------------------
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # types are in the numpydoc Parameters sections
autodoc_default_options = {"show-inheritance": True}
autosummary_generate = True
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# -- Example gallery ------------------------------------------------------------------------
sphinx_gallery_conf = {
    "examples_dirs": "../examples",
    "gallery_dirs": "auto_examples",
    "filename_pattern": r"/plot_",  # every examples/plot_*.py is executed
    "ignore_pattern": r"__init__\.py",
    "within_subsection_order": "FileNameSortKey",  # order by name: plot_01_..., plot_02_...
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "reset_modules": ("matplotlib",),
    "image_scrapers": ("matplotlib",),
    "capture_repr": ("_repr_html_", "__repr__"),
    "download_all_examples": False,
    "remove_config_comments": True,
    "min_reported_time": 1,
    # the animations of rigidmech.drawing.animate, embedded as JavaScript players (no ffmpeg)
    "matplotlib_animations": (True, "jshtml"),
}

# -- HTML -----------------------------------------------------------------------------------
html_theme = "alabaster"
html_title = f"rigidmech {release}"
html_theme_options = {
    "description": "Mechanics of rigid bodies the way Berthelot's textbook teaches it",
    "fixed_sidebar": True,
    "show_relbars": True,
}
html_static_path: list[str] = []
