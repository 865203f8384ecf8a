#!/usr/bin/python3
"""Runs every code block of a documentation page as a user would, and fails on the first that fails.

Usage: /usr/bin/python3 tests/check_docs.py BUILD_DIR SOURCE_DIR PAGE.md WORK_DIR

HOME is WORK_DIR/home, and the build is installed as the pages say, into ~/.local, with the
environment the installation page sets up (~/.local/bin on PATH, the module's folder on
PYTHONPATH), so the test touches nothing outside WORK_DIR. The page's blocks then run in order in
~/PAGE, a directory outside the checkout:

- ```sh / ```bash: run by `bash -e -o pipefail`; they share the page's directory (and so its files);
- ```python: run by Debian's /usr/bin/python3, each block a script of its own;
- ```toml, ```cpp, ```cmake and any other block preceded by `<!-- file: NAME -->`: written to NAME
  for the blocks after it (a TOML block must be a file that a later block uses; it is parsed here);
- ```text: output or a synopsis, never run.

Comments just before a block change how it runs:
- `<!-- file: NAME -->` as above;
- `<!-- in: checkout -->`: run in a directory that stands for the user's checkout (its `build`
  is this build, its `studies` the source's);
- `<!-- status: N -->`: the block must exit with status N (an example of a refusal);
- `<!-- not run: REASON -->`: the block is not run, for the reason given (it must be given), e.g.
  the commands CI itself runs. The reasons are printed.
"""
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path

RUN = {"sh", "bash", "shell", "python", "py"}
WRITE_ONLY = {"toml", "cpp", "c++", "cmake", "csv", "ini"}
NEVER = {"text", "console", "none", ""}
DIRECTIVE = re.compile(r"^\{.*\}")  # MyST directives (```{toctree}, ```{include}, ...) are not code
ANNOTATION = re.compile(r"<!--\s*(file|in|status|not run)\s*:\s*(.*?)\s*-->")
BLOCK_TIMEOUT_S = 600


def blocks(text):
    """Yields (line, language, annotations, code) for each fenced block of a Markdown page."""
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        fence = re.match(r"^(`{3,}|~{3,})(.*)$", lines[i])
        if not fence:
            i += 1
            continue
        marker, info = fence.group(1), fence.group(2).strip()
        start = i
        body = []
        i += 1
        while i < len(lines) and not lines[i].startswith(marker):
            body.append(lines[i])
            i += 1
        i += 1
        notes = {}
        j = start - 1
        while j >= 0 and ANNOTATION.search(lines[j]):
            for key, value in ANNOTATION.findall(lines[j]):
                notes[key] = value
            j -= 1
        yield start + 1, info.split()[0].lower() if info else "", notes, "\n".join(body) + "\n"


def indented_code(text):
    """Line numbers of indented code blocks, which this checker cannot run: pages must fence code."""
    found = []
    in_fence = False
    previous_blank = True
    in_list = False
    for number, line in enumerate(text.split("\n"), 1):
        if re.match(r"^(`{3,}|~{3,})", line):
            in_fence = not in_fence
        elif not in_fence:
            if re.match(r"^\s*([-*+]|\d+\.)\s", line):
                in_list = True
            elif line.strip() == "":
                pass
            elif not line.startswith(" "):
                in_list = False
            if line.startswith("    ") and previous_blank and not in_list and line.strip():
                found.append(number)
        previous_blank = line.strip() == ""
    return found


def environment(home):
    prefix = home / ".local"
    env = {
        "HOME": str(home),
        "PATH": f"{prefix / 'bin'}:/usr/bin:/bin",
        "PYTHONPATH": str(prefix / "lib" / "python3" / "dist-packages"),
        "MPLBACKEND": "Agg",
        "LANG": "C.UTF-8",
        "OMPI_ALLOW_RUN_AS_ROOT": "1",
        "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1",
        "OMPI_MCA_rmaps_base_oversubscribe": "1",
        "OMP_NUM_THREADS": "1",
    }
    return env


def checkout_stand_in(work, build, source):
    """A directory that looks like the user's checkout to the commands a page runs there."""
    checkout = work / "checkout"
    checkout.mkdir(exist_ok=True)
    for name, target in (("build", build), ("studies", source / "studies"), ("scripts", source / "scripts")):
        link = checkout / name
        if not link.exists():
            link.symlink_to(target)
    return checkout


def run_block(page, line, language, notes, code, cwd, env):
    where = f"{page.name}:{line}"
    expected = int(notes.get("status", "0"))
    if language in {"python", "py"}:
        script = cwd / f".block_{line}.py"
        script.write_text(code)
        command = ["/usr/bin/python3", str(script)]
    else:
        command = ["bash", "-e", "-o", "pipefail", "-c", code]
    print(f"--- {where} ({language}) in {cwd}", flush=True)
    result = subprocess.run(command, cwd=cwd, env=env, capture_output=True, text=True, timeout=BLOCK_TIMEOUT_S)
    sys.stdout.write(result.stdout[-4000:])
    sys.stderr.write(result.stderr[-4000:])
    if result.returncode != expected:
        sys.exit(f"{where}: the {language} block exited with {result.returncode}, expected {expected}")


def check_page(build, source, page, work):
    text = page.read_text()
    if indented := indented_code(text):
        sys.exit(f"{page.name}: indented code at line(s) {indented}: fence it with a language")
    shutil.rmtree(work, ignore_errors=True)
    home = work / "home"
    env = environment(home)
    subprocess.run(["cmake", "--install", str(build), "--prefix", str(home / ".local")], check=True,
                   stdout=subprocess.DEVNULL)
    cwd = home / page.stem
    cwd.mkdir(parents=True)
    checkout = checkout_stand_in(work, build, source)
    ran = skipped = 0
    unused = {}  # files written and not yet named by a later block
    for line, language, notes, code in blocks(text):
        if DIRECTIVE.match(language) or language in NEVER:
            continue
        if "not run" in notes:
            if not notes["not run"]:
                sys.exit(f"{page.name}:{line}: 'not run' needs a reason")
            print(f"--- {page.name}:{line} not run: {notes['not run']}")
            skipped += 1
            continue
        if "file" in notes:
            target = cwd / notes["file"]
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(code)
            unused = {name: at for name, at in unused.items() if name not in code}
            unused[notes["file"]] = line
            if language == "toml":
                try:
                    tomllib.loads(code)
                except tomllib.TOMLDecodeError as error:
                    sys.exit(f"{page.name}:{line}: not TOML: {error}")
            continue
        if language in WRITE_ONLY:
            sys.exit(f"{page.name}:{line}: a {language} block needs <!-- file: NAME --> so that it is used")
        if language not in RUN:
            sys.exit(f"{page.name}:{line}: unknown block language {language!r} (use text for output)")
        run_block(page, line, language, notes, code, checkout if notes.get("in") == "checkout" else cwd, env)
        unused = {name: at for name, at in unused.items() if name not in code}
        ran += 1
    if unused:
        sys.exit(f"{page.name}: file block(s) that no later block uses: {unused}")
    print(f"{page.name}: {ran} blocks ran, {skipped} not run")


if __name__ == "__main__":
    build_dir, source_dir, page_path, work_dir = (Path(p).resolve() for p in sys.argv[1:5])
    check_page(build_dir, source_dir, page_path, work_dir)
