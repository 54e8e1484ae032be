#!/usr/bin/env python3
"""Every command line in README.md and docs/*.md that runs `globe`, run (issue 37, item 9).

Usage: docs_commands_test.py GLOBE SOURCE_DIR WORKDIR

Each document's fenced blocks that hold a `globe` command run in order as one shell session (a `cd`
or a file written in one block holds for the next), in WORKDIR/<document>/ with the repository's
assets/, tests/ and scripts/ linked in, so the commands run as written from the repository root.
A block whose lines start with `$ ` runs only those lines (the rest is their output). Blocks fenced
as ```text are synopses and not run; a block fenced with `file=NAME` (```toml file=bad.toml) is
written to NAME for the commands after it. A command ending in `# exits N` must exit with N, every
other one with 0, and none may hit a budget (a `globe: warning:` about a budget or a pool: each
preset must fit its own defaults at every camera the docs show, issue 37 item 8). `globe` is a wrapper that makes the work small (docs_globe_wrapper.py): frame
sizes, path rates, frame counts; the commands are otherwise the documents' own.
"""
import os
import re
import shlex
import subprocess
import sys
import time
from pathlib import Path

COMMAND = re.compile(r"^\s*(\$ )?([A-Z_]+=\S+\s+)*(xvfb-run\s.*\s)?(\S*/)?globe\s")
EXITS = re.compile(r"#\s*exits (\d+)\b")


def blocks(markdown):
    """(first line number, info string, lines) of each fenced block."""
    out, inside, info, start, body = [], False, "", 0, []
    for number, line in enumerate(markdown.split("\n"), 1):
        fence = line.strip()
        if fence.startswith("```"):
            if inside:
                out.append((start, info, body))
            else:
                info, start, body = fence[3:].strip(), number + 1, []
            inside = not inside
        elif inside:
            body.append(line)
    return out


def commands(start, body):
    """(line number, command) for each command of a block, continuation lines joined."""
    prompted = any(line.startswith("$ ") for line in body)
    out, k = [], 0
    while k < len(body):
        number, line = start + k, body[k]
        while line.rstrip().endswith("\\") and k + 1 < len(body):
            k += 1
            line = line.rstrip()[:-1] + " " + body[k].strip()
        k += 1
        if prompted:
            if not line.startswith("$ "):
                continue
            line = line[2:]
        if line.strip() and not line.strip().startswith("#"):
            out.append((number, line.strip()))
    return out


def script_for(document, source):
    """The shell script of one document, or None when it runs no `globe` command."""
    lines, runs = ["set -u", "failures=0"], 0
    for start, info, body in blocks(document.read_text()):
        words = info.split()
        named = [w[5:] for w in words if w.startswith("file=")]
        if named:
            lines.append(f"cat > {shlex.quote(named[0])} <<'DOCS_EOF'\n" + "\n".join(body) + "\nDOCS_EOF")
            continue
        if words[:1] == ["text"] or not any(COMMAND.match(line) for line in body):
            continue
        for number, command in commands(start, body):
            where = f"{document.relative_to(source)}:{number}"
            expected = EXITS.search(command)
            code = int(expected.group(1)) if expected else 0
            lines.append(
                f"t0=$EPOCHREALTIME; {{ {command}\n}} >\"$LOGS/{runs}.log\" 2>&1; code=$?\n"
                f"dt=$(awk -v a=$t0 -v b=$EPOCHREALTIME 'BEGIN {{ printf \"%.1f\", b - a }}')\n"
                f"if [[ $code -ne {code} ]]; then echo \"FAIL ({where}, exit $code, want {code}):\" {shlex.quote(command)}; "
                f"tail -5 \"$LOGS/{runs}.log\"; failures=$((failures + 1))\n"
                f"elif grep -q '^globe: warning: .*\\(budget\\|pool\\)' \"$LOGS/{runs}.log\"; then "
                f"echo \"FAIL ({where}, a budget hit):\" {shlex.quote(command)}; grep '^globe: warning' \"$LOGS/{runs}.log\"; "
                f"failures=$((failures + 1))\n"
                f"else echo \"ok ($dt s) {where}:\" {shlex.quote(command[:110])}; fi"
            )
            runs += 1
    if runs == 0:
        return None
    lines.append("exit $((failures > 0))")
    return "\n".join(lines) + "\n"


def prepare(work, source, globe):
    """WORK with the repository's data linked in and `globe` (also as build/*/bin/globe) the wrapper."""
    work.mkdir(parents=True)
    for name in ("assets", "tests", "scripts"):
        (work / name).symlink_to(source / name)
    wrapper = Path(__file__).with_name("docs_globe_wrapper.py")
    bin_dir = work / ".bin"
    bin_dir.mkdir()
    (bin_dir / "globe").symlink_to(wrapper)
    for build in ("release", "ci"):
        (work / "build" / build / "bin").mkdir(parents=True)
        (work / "build" / build / "bin" / "globe").symlink_to(wrapper)
    env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}", SRC=str(source), GLOBE_REAL=globe,
               LOGS=str(work / ".logs"))
    (work / ".logs").mkdir()
    return env


def main():
    globe, source, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    subprocess.run(["rm", "-rf", str(work)], check=True)
    documents = [source / "README.md"] + sorted((source / "docs").glob("*.md"))
    failed, start = [], time.monotonic()
    for document in documents:
        script = script_for(document, source)
        if script is None:
            continue
        directory = work / document.stem
        env = prepare(directory, source, str(globe))
        print(f"== {document.relative_to(source)}", flush=True)
        if subprocess.run(["bash", "-c", script], cwd=directory, env=env).returncode != 0:
            failed.append(str(document.relative_to(source)))
    print(f"{time.monotonic() - start:.0f} s")
    if failed:
        print("FAIL: commands failed in " + ", ".join(failed))
        return 1
    print("every documented globe command ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
