"""Runs the documented commands of one Markdown file as written, and fails when one fails.

    run_docs_commands.py SOURCE_DIR BUILD_DIR DOC.md [--no-benchmarks]

--no-benchmarks: the build was configured without the benchmarks (MPMICE_BUILD_BENCHMARKS=OFF, as
the sanitizer build is): a [long] or [system] line's programs under build/benchmarks/ cannot exist
there and are not checked (counted and printed); every other check is unchanged.

The convention (README.md, "Documents"): a fenced block tagged `sh` or `python` is a runnable
example. The blocks of a document run in order, in one scratch directory in which `build` is the
build directory and `configs`, `scripts`, `tests`, `benchmarks`, `python`, `docs`, ... are the
source tree's, so what one block writes (`output/...`) the next can read.

- `sh`: the block runs as one bash script with `set -euo pipefail` and must exit 0. A line whose
  comment holds `[long]` (runs for minutes, builds) or `[system]` (installs packages or writes
  outside the scratch directory) is shown in the document as written but not run; the files and
  programs it names under build/, configs/, scripts/, ... must exist. An unmarked line that
  builds, installs or reconfigures (cmake, ctest, make, apt-get, scripts/{run,test,setup}.sh) is
  an error, never run.
- `python`: the block runs as a script through scripts/python (h5py, numpy, python/mpmice) and
  must exit 0.
Untagged blocks (terminal output, file layouts) are not run.
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

MARKERS = ("[long]", "[system]")
TREE = ("configs", "scripts", "tests", "benchmarks", "python", "docs", "adapters", "apps", "src", "cmake",
        "CMakeLists.txt", "README.md")
TIMEOUT = 600


def blocks(path):
    """(tag, first line number, lines) of every fenced block."""
    found, tag, start, body = [], None, 0, []
    with open(path) as f:
        for n, line in enumerate(f, start=1):
            fence = re.match(r"^```\s*([\w+-]*)", line)
            if fence and tag is None:
                tag, start, body = fence.group(1) or "-", n + 1, []
            elif fence:
                found.append((tag, start, body))
                tag = None
            elif tag is not None:
                body.append(line.rstrip("\n"))
    return found


def comment_of(line):
    """The text after the first # that starts a word (a shell comment), or ''."""
    m = re.search(r"(^|\s)#(.*)$", line)
    return m.group(2) if m else ""


def named_paths(line):
    """Relative paths into the tree or the build a command names (before its comment)."""
    code = line.split(" #", 1)[0]
    try:
        words = shlex.split(code)
    except ValueError:
        return []
    out = []
    for w in words:
        w = w.split("=", 1)[-1]
        head = w.split("/", 1)[0]
        if "/" in w and "$" not in w and (head in TREE or head.startswith("build")):
            out.append(w)
    return out


# Commands that rebuild, reinstall or reconfigure: never run, whatever the document says.
NEVER = re.compile(r"(^|[;&|(]\s*)(cmake\s|ctest\s|make\s|apt-get\s|bash scripts/(run|test|setup|sanitize)\.sh)")


def scratch(source, build):
    """The scratch directory. Its `build` is a directory of links to the build's entries, without
    the build's CMake cache and makefiles, so nothing run there can reconfigure the real build."""
    d = tempfile.mkdtemp(prefix="docs_commands_")
    os.mkdir(os.path.join(d, "build"))
    for name in os.listdir(build):
        if name not in ("CMakeCache.txt", "CMakeFiles", "Makefile", "build.ninja", "cmake_install.cmake"):
            os.symlink(os.path.join(build, name), os.path.join(d, "build", name))
    for name in TREE:
        if os.path.exists(os.path.join(source, name)):
            os.symlink(os.path.join(source, name), os.path.join(d, name))
    return d


def main():
    source, build, doc = (os.path.abspath(a) for a in sys.argv[1:4])
    benchmarks_built = "--no-benchmarks" not in sys.argv[4:]
    unchecked = 0
    rel = os.path.relpath(doc, source)
    work = scratch(source, build)
    ran = skipped = 0
    failures = []
    for tag, start, body in blocks(doc):
        if tag not in ("sh", "python"):
            continue
        where = f"{rel}:{start}"
        if tag == "python":
            script = os.path.join(work, f"block_{start}.py")
            with open(script, "w") as f:
                f.write("\n".join(body) + "\n")
            cmd = [os.path.join(source, "scripts", "python"), script]
            shown = f"python block at {where}"
            ran += 1
        else:
            lines, joined = [], ""
            for n, line in enumerate(body):
                joined = joined + line[:-1] + " " if line.endswith("\\") else joined + line
                if line.endswith("\\"):
                    continue
                text, joined = joined, ""
                if not text.strip() or text.lstrip().startswith("#"):
                    continue
                if any(m in comment_of(text) for m in MARKERS):
                    skipped += 1
                    for p in named_paths(text):
                        if not benchmarks_built and p.startswith("build/benchmarks/"):
                            unchecked += 1
                            continue
                        if not os.path.exists(os.path.join(work, p)):
                            failures.append(f"{rel}:{start + n}: '{p}' does not exist (in: {text.strip()})")
                    continue
                if NEVER.search(text.split(" #", 1)[0]):
                    failures.append(f"{rel}:{start + n}: builds, installs or reconfigures: mark it [long] or "
                                    f"[system] (in: {text.strip()})")
                    continue
                lines.append(text)
                ran += 1
            if not lines:
                continue
            cmd = ["bash", "-c", "set -euo pipefail -x\n" + "\n".join(lines)]
            shown = f"sh block at {where}: " + " ; ".join(l.split(" #")[0].strip() for l in lines)
        print(f"run: {shown}", flush=True)
        try:
            r = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                               timeout=TIMEOUT)
            status, text = r.returncode, r.stdout
        except subprocess.TimeoutExpired as e:
            status, text = f"timeout after {TIMEOUT} s", (e.stdout or b"").decode(errors="replace")
        if status != 0:
            tail = "\n".join(text.splitlines()[-40:])
            failures.append(f"{shown}: exit {status}\n{tail}")
    for f in failures:
        print("FAIL: " + f)
    if failures:
        print(f"(scratch directory kept: {work})")
        return 1
    subprocess.run(["rm", "-rf", work])
    note = f", {unchecked} benchmark paths not checked (benchmarks not built)" if unchecked else ""
    print(f"PASS: docs commands: {rel}: {ran} run, {skipped} marked [long]/[system] not run{note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
