#!/usr/bin/python3
"""CITATION.cff against CMake's project version: a release that bumps one must bump the other.

Usage: check_citation.py CITATION.cff PROJECT_VERSION
Reads the file with PyYAML (Debian's python3-yaml) when it is there, else the top-level
`version:` line alone.
"""
import re
import sys

path, project_version = sys.argv[1], sys.argv[2]
with open(path, encoding="utf-8") as f:
    text = f.read()
try:
    import yaml
except ImportError:
    yaml = None
if yaml:
    cff = yaml.safe_load(text)
    for key in ("cff-version", "title", "version", "authors", "references"):
        if key not in cff:
            sys.exit(f"{path}: no {key}")
    version = str(cff["version"])
    dois = [r.get("doi") for r in cff["references"]]
    if "10.1119/1.1285945" not in dois:
        sys.exit(f"{path}: references lack N2000 (doi 10.1119/1.1285945): {dois}")
else:
    found = re.search(r"^version:\s*['\"]?([^'\"\s#]+)", text, re.MULTILINE)
    if not found:
        sys.exit(f"{path}: no top-level version")
    version = found.group(1)
if version != project_version:
    sys.exit(f"{path}: version {version}, but CMakeLists.txt's project version is {project_version}")
print(f"{path}: version {version} = the project's ({'yaml' if yaml else 'line check'})")
