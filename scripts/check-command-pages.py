#!/usr/bin/env python3
"""Checks that every command's page lists every option its --help prints.

Runs `WHIRL --help` for the list of subcommands, then `WHIRL <command> --help` for each, and reads
the option names (--name, and -x short forms) of its Options section. The command's page,
docs/user/commands/<command>.md, must exist and name each of them (as `--name`, a whole word: `--rpm`
is not found in `--rpm-file`). A page for a command `whirl --help` does not list is reported too.
Usage: check-command-pages.py WHIRL REPO_ROOT; one line per problem, exit 1 if any.
"""
import pathlib
import re
import subprocess
import sys

SECTION = re.compile(r"^([A-Za-z][A-Za-z ]*):\s*$")
ENTRY = re.compile(r"^\s+(\S+)")
OPTION_NAMES = re.compile(r"^\s+((?:-{1,2}[A-Za-z0-9][\w-]*,?)+)")


def help_text(whirl, *args):
    run = subprocess.run([whirl, *args, "--help"], capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        raise SystemExit(f"check-command-pages: `{' '.join([whirl, *args])} --help` exited {run.returncode}: {run.stderr}")
    return run.stdout


def sections(text):
    """{section title (lower case): its lines} of a CLI11 help text."""
    found, current = {}, None
    for line in text.splitlines():
        m = SECTION.match(line)
        if m:
            current = found.setdefault(m.group(1).strip().lower(), [])
        elif current is not None and line.strip():
            current.append(line)
    return found


def subcommands(whirl):
    lines = sections(help_text(whirl)).get("subcommands", [])
    return [m.group(1) for line in lines if (m := ENTRY.match(line))]


def options(whirl, command):
    names = []
    for line in sections(help_text(whirl, command)).get("options", []):
        m = OPTION_NAMES.match(line)
        if m:
            names += [n for n in m.group(1).split(",") if n and n not in ("-h", "--help")]
    return names


def mentioned(page_text, name):
    return re.search(r"(?<![\w-])" + re.escape(name) + r"(?![\w-])", page_text) is not None


def main():
    if len(sys.argv) != 3:
        raise SystemExit("usage: check-command-pages.py WHIRL REPO_ROOT")
    whirl, root = sys.argv[1], pathlib.Path(sys.argv[2])
    pages_dir = root / "docs" / "user" / "commands"
    commands = subcommands(whirl)
    if not commands:
        raise SystemExit(f"check-command-pages: `{whirl} --help` lists no subcommands")
    problems, checked = [], 0
    for command in commands:
        page = pages_dir / f"{command}.md"
        if not page.exists():
            problems.append(f"whirl {command}: no page {page.relative_to(root)}")
            continue
        text = page.read_text(encoding="utf-8")
        for name in options(whirl, command):
            checked += 1
            if not mentioned(text, name):
                problems.append(f"{page.relative_to(root)}: option {name} of `whirl {command} --help` not listed")
    for page in sorted(pages_dir.glob("*.md")):
        if page.stem not in commands and page.stem != "index":
            problems.append(f"{page.relative_to(root)}: `whirl --help` has no command '{page.stem}'")
    for p in problems:
        print(f"check-command-pages: {p}")
    print(f"check-command-pages: {len(commands)} commands, {checked} options, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
