"""Runs the README's Python example (the first ```python block of its "## Python" section) as
written, from a scratch folder laid out as the repository's top: `studies` and `build/python` link
to the real ones, so that the figure it saves lands in the scratch folder.

    /usr/bin/python3 tests/check_readme_python.py MODULE_DIR README WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

module_dir, readme, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve(), Path(sys.argv[3])
text = readme.read_text()
section = text[text.index("\n## Python\n"):]
section = section[:section.index("\n## ", 1)]
code = re.search(r"```python\n(.*?)```", section, re.S).group(1)

shutil.rmtree(work, ignore_errors=True)
(work / "build").mkdir(parents=True)
(work / "studies").symlink_to(readme.parent / "studies")
(work / "build" / "python").symlink_to(module_dir)
(work / "example.py").write_text(code)
run = subprocess.run([sys.executable, "example.py"], cwd=work, capture_output=True, text=True,
                     env=os.environ | {"MPLBACKEND": "Agg"})
print(run.stdout, run.stderr)
assert run.returncode == 0, "the README's Python example failed"
assert "sweet spot: z = " in run.stdout, "no sweet spot printed"
assert (work / "vf_z.png").stat().st_size > 1000, "no figure"
print("README Python example: ran as written")
