#!/usr/bin/env python3
"""Runs the code blocks of Markdown files as written, so that every documented command keeps working.

    tests/doc_blocks.py [--list] [--block N] FILE.md ...

Every fenced block must name its language (an indented or unnamed block is an error: a command
in it would be run by nobody). What runs:

- ```sh: the block, in one `bash -e -o pipefail`; it passes when its last command exits 0.
- ```console: commands after `$ ` (a line ending in `\\` continues), each followed by the output
  it must print (stdout and stderr together). `...` in an expected line matches any text, a line
  of `...` alone any number of lines, so times and paths need not match. A last line `[N]`
  expects exit status N instead of 0.
- ```python: the block, in python3.
Other languages (cpp, yaml, ini, text, ...) are shown code, not run.

Commands in the prose (`acoplan --scen data/terrain/epf20.asc.scen --svg run.svg`) are not run,
but the files they read must exist: a file that does not is a placeholder, and a placeholder must
look like one (`<your.map>`, `SCENARIO.yaml`), never like a plausible file name (`my.map`).

An HTML comment on the line before a block, `<!-- doc-test: skip: REASON -->`, skips it; the
reason is printed (needs MPI or Slurm, builds the project, takes minutes).

Each block runs in a fresh folder holding links to every entry of the project's root (and of
its build/), after
`. tools/env.sh` (the README's set-up line), with HOME a fresh folder too: relative paths resolve
as from the root, and files a block writes stay out of the checkout.
"""
import argparse
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field

RUN_LANGUAGES = {"sh", "console", "python"}
TIMEOUT_S = 300


@dataclass
class Block:
    file: str
    line: int  # of the opening fence, 1-based
    language: str
    text: str
    skip: str = ""  # the reason, when skipped


@dataclass
class Problem:
    file: str
    line: int
    message: str


def parse(path, display):
    """The fenced blocks of a Markdown file, and what is wrong with its blocks."""
    blocks, problems = [], []
    lines = open(path, encoding="utf-8").read().split("\n")
    i, previous_blank, in_list = 0, True, False
    while i < len(lines):
        line = lines[i]
        fence = re.match(r"^(\s*)(```+|~~~+)(.*)$", line)
        if fence:
            indent, marker, info = fence.group(1), fence.group(2), fence.group(3).strip()
            body, j = [], i + 1
            while j < len(lines) and not lines[j].strip().startswith(marker):
                body.append(lines[j][len(indent):] if lines[j].startswith(indent) else lines[j])
                j += 1
            language = info.split()[0] if info else ""
            if not language:
                problems.append(Problem(display, i + 1, "a code block without a language: write ```sh (run by "
                                        "this test), ```console, ```text or the code's language"))
            skip = ""
            k = i - 1
            while k >= 0 and not lines[k].strip():
                k -= 1
            marker_comment = re.match(r"^\s*<!--\s*doc-test:\s*skip:\s*(.+?)\s*-->\s*$", lines[k]) if k >= 0 else None
            if marker_comment:
                skip = marker_comment.group(1)
            blocks.append(Block(display, i + 1, language, "\n".join(body) + "\n", skip))
            i, previous_blank = j + 1, False
            continue
        # An indented code block: four spaces after a blank line, outside a list item.
        if line.strip() and not line.startswith(" "):
            in_list = bool(re.match(r"^(\s*[-*+]|\s*\d+[.)])\s", line)) or (in_list and not previous_blank)
        if previous_blank and not in_list and line.startswith("    ") and line.strip() and not line.lstrip().startswith("|"):
            problems.append(Problem(display, i + 1, "an indented code block: fence it and name its language "
                                    "(```sh is run by this test)"))
            while i < len(lines) and (lines[i].startswith("    ") or not lines[i].strip()):
                i += 1
            previous_blank = True
            continue
        previous_blank = not line.strip()
        i += 1
    return blocks, problems


PROGRAMS = (r"(acoplan|acobench|acosim|aco-plugin-check|aco-new-plugin|aco_mapgen|aco_terraingen|aco_bench|aco-irace"
            r"|tools/[\w.-]+|build/release/[\w/.-]+)")
OUTPUT_OPTIONS = {"--svg", "--out", "--db", "--csv", "--html", "--dump-irace-params", "--shard", "--benchmark"}
SLOTS = r"(init|heuristic|update|deadlock|smoother|local|map)"
# Map generators: a path without a file extension is the folder they write into.
GENERATORS = r"(.*/)?(aco_mapgen|aco_terraingen)"


def inline_command_problems(path, display, root):
    """Files read by the commands in a file's prose (`...` spans) that do not exist in the project."""
    text = open(path, encoding="utf-8").read()
    problems = []
    for span in re.finditer(r"`([^`\n]+)`", re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)):
        words = span.group(1).split()
        if not re.fullmatch(PROGRAMS, words[0]) or len(words) < 2:
            continue
        generator = re.fullmatch(GENERATORS, words[0])
        for previous, word in zip(words, words[1:]):
            word = word.rstrip(",;")
            # Databases, pictures and pages are what the programs write (a positional output such
            # as aco_voxel_sample's), not what they read.
            if word.startswith("-") or "=" in word or previous in OUTPUT_OPTIONS or word.endswith((".db", ".svg", ".html")):
                continue
            if generator and "." not in os.path.basename(word):
                continue
            if not (re.search(r"\.(map|scen|yaml|ini|asc|pgm|txt|so|shapes)$", word) or "/" in word):
                continue
            stem = os.path.basename(word).split(".")[0]
            if (word.startswith("<") or (stem.isupper() and stem) or re.fullmatch(SLOTS + r"/\w+", word)
                    or re.fullmatch(r"[A-Z]+/[A-Z]+", word)
                    # Only the project's files count: an absolute path that exists on one machine
                    # (/tmp/tune, left by an earlier run) is missing on CI's fresh one.
                    or (not os.path.isabs(word) and glob.glob(os.path.join(root, word)))):
                continue
            line = text.count("\n", 0, span.start()) + 1
            problems.append(Problem(display, line, f"`{span.group(1)}` reads {word}, which the project does not have: "
                                    "use a bundled file, or a placeholder that looks like one (<your.map>)"))
    return problems


def console_steps(text):
    """(command, expected output lines, expected status) per `$ ` command of a console block."""
    steps, command, expected = [], None, []
    lines = text.rstrip("\n").split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("$ "):
            if command is not None:
                steps.append((command, expected))
            command, expected = lines[i][2:], []
            while command.endswith("\\") and i + 1 < len(lines):
                i += 1
                command = command + "\n" + lines[i]
        elif command is not None:
            expected.append(lines[i])
        i += 1
    if command is not None:
        steps.append((command, expected))
    result = []
    for command, expected in steps:
        status = 0
        if expected and re.fullmatch(r"\[\d+\]", expected[-1].strip()):
            status = int(expected[-1].strip()[1:-1])
            expected = expected[:-1]
        result.append((command, expected, status))
    return result


def matches(expected, actual):
    """Whether the actual output lines match the expected ones (`...` wildcards)."""
    def line_pattern(line):
        return re.compile("^" + ".*".join(re.escape(part) for part in line.rstrip().split("...")) + "$")

    patterns = [None if line.strip() == "..." else line_pattern(line) for line in expected]
    actual = [line.rstrip() for line in actual]
    memo = {}

    def match(p, a):
        if (p, a) in memo:
            return memo[(p, a)]
        if p == len(patterns):
            ok = a == len(actual)
        elif patterns[p] is None:
            ok = any(match(p + 1, k) for k in range(a, len(actual) + 1))
        else:
            ok = a < len(actual) and bool(patterns[p].match(actual[a])) and match(p + 1, a + 1)
        memo[(p, a)] = ok
        return ok

    return match(0, 0)


def workspace(root, python):
    """A fresh folder that looks like the project's root, a fresh HOME, and `python3` the build's."""
    work = tempfile.mkdtemp(prefix="doc-block-")
    for entry in os.listdir(root):
        if entry != "build":
            os.symlink(os.path.join(root, entry), os.path.join(work, entry))
    # build/ itself is the block's own, so that a block may build into it (build/shapes_map); the
    # build trees in it are the project's.
    os.mkdir(os.path.join(work, "build"))
    for entry in os.listdir(os.path.join(root, "build")) if os.path.isdir(os.path.join(root, "build")) else []:
        os.symlink(os.path.join(root, "build", entry), os.path.join(work, "build", entry))
    home = os.path.join(work, ".home")
    shims = os.path.join(work, ".bin")
    os.mkdir(home)
    os.mkdir(shims)
    os.symlink(python, os.path.join(shims, "python3"))
    return work, home, shims


def run(block, root, preset, python):
    """None if the block passed, else what went wrong."""
    work, home, shims = workspace(root, python)
    env = dict(os.environ, HOME=home, ACO_PRESET=preset, MPLBACKEND="Agg", PATH=shims + ":" + os.environ["PATH"])
    setup = ". tools/env.sh\n"
    try:
        if block.language == "sh":
            proc = subprocess.run(["bash", "-e", "-o", "pipefail", "-c", setup + block.text], cwd=work, env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT_S)
            if proc.returncode != 0:
                return f"exit status {proc.returncode}; its output:\n" + tail(proc.stdout)
        elif block.language == "python":
            proc = subprocess.run(["bash", "-c", setup + 'exec python3 -c "$0"', block.text], cwd=work, env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT_S)
            if proc.returncode != 0:
                return f"exit status {proc.returncode}; its output:\n" + tail(proc.stdout)
        else:
            for command, expected, status in console_steps(block.text):
                proc = subprocess.run(["bash", "-o", "pipefail", "-c", setup + command], cwd=work, env=env,
                                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=TIMEOUT_S)
                if proc.returncode != status:
                    return f"$ {command}\nexit status {proc.returncode}, expected {status}; its output:\n" + tail(proc.stdout)
                if not matches(expected, proc.stdout.rstrip("\n").split("\n") if proc.stdout.strip() else []):
                    return (f"$ {command}\nprinted:\n{proc.stdout}\nexpected (... matches anything):\n" + "\n".join(expected))
        return None
    except subprocess.TimeoutExpired:
        return f"still running after {TIMEOUT_S} s (mark a block that takes minutes <!-- doc-test: skip: ... -->)"
    finally:
        shutil.rmtree(work, ignore_errors=True)


def tail(text, lines=40):
    parts = text.rstrip("\n").split("\n")
    return "\n".join(parts[-lines:])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                        help="the project's root (default: this checkout)")
    parser.add_argument("--preset", default="release", help="the build preset whose programs run (tools/env.sh)")
    parser.add_argument("--python", default=sys.executable,
                        help="the interpreter `python3` means in the blocks (the one the package is built for)")
    parser.add_argument("--list", action="store_true", help="list the blocks and exit")
    parser.add_argument("--block", type=int, action="append", help="run only the block opening at this line")
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    failures, ran, skipped, start = 0, 0, [], time.monotonic()
    for name in args.files:
        path = name if os.path.isabs(name) else os.path.join(root, name)
        blocks, problems = parse(path, os.path.relpath(path, root))
        problems += inline_command_problems(path, os.path.relpath(path, root), root)
        for problem in problems:
            print(f"FAIL {problem.file}:{problem.line}: {problem.message}")
        failures += len(problems)
        for block in blocks:
            if block.language not in RUN_LANGUAGES or (args.block and block.line not in args.block):
                continue
            where = f"{block.file}:{block.line} ({block.language})"
            if block.skip:
                skipped.append((where, block.skip))
                print(f"SKIP {where}: {block.skip}")
                continue
            if args.list:
                print(f"RUN  {where}")
                continue
            began = time.monotonic()
            error = run(block, root, args.preset, args.python)
            ran += 1
            if error:
                failures += 1
                print(f"FAIL {where}: " + error)
            else:
                print(f"ok   {where} ({time.monotonic() - began:.1f} s)")
            sys.stdout.flush()
    print(f"doc blocks: {ran} run, {failures} failed, {len(skipped)} skipped, {time.monotonic() - start:.0f} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
