# Sphinx configuration of sweetspot's documentation (built by `sphinx-build -W docs OUT`, a test).
import re
from pathlib import Path

source = Path(__file__).resolve().parent.parent
version_line = re.search(r"project\(sweetspot\s+VERSION\s+([0-9.]+)", (source / "CMakeLists.txt").read_text())

project = "sweetspot"
author = "The sweetspot authors"
copyright = "2026, the sweetspot authors"
release = version = version_line.group(1) if version_line else "unknown"

extensions = ["myst_parser", "sphinx.ext.autodoc"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "validation", "examples", "README.md"]
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]
html_theme = "furo"
html_title = f"sweetspot {release}"
autodoc_member_order = "bysource"
