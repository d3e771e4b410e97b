#!/usr/bin/env python3
"""Writes mbc's man pages (with help2man) and its bash completion from the
help that mbc prints, so that the commands and options are written once,
in driver/command_line.cpp.

Usage: command_docs.py MBC --man DIR --completion FILE
"""
import argparse
import os
import re
import subprocess
import sys

# "  NAME...   description", the first line of an entry of a help section.
ENTRY = re.compile(r"^  (\S+(?:, \S+)*)(?: (\S+))?(?:\s{2,}(.*))?$")


def help_text(mbc, *args):
    return subprocess.run([mbc, *args], check=True, capture_output=True,
                          text=True).stdout


def sections(text):
    """{section name: [(names, value, description)]} of a help text."""
    out, current = {}, None
    for line in text.splitlines():
        if re.match(r"^[A-Z][A-Za-z ]*:$", line):
            current = out.setdefault(line[:-1], [])
        elif current and line.startswith("    "):
            # A description wrapped onto the next line.
            names, value, description = current[-1]
            current[-1] = (names, value, f"{description} {line.strip()}"
                           if description else line.strip())
        elif current is not None and line.startswith("  ") and \
                not line.startswith("   "):
            m = ENTRY.match(line)
            if m:
                names, value, description = m.groups()
                current.append((re.split(r",\s*", names), value or "",
                                description or ""))
        elif not line.startswith(" "):
            current = None
    return out


def commands(mbc):
    return [(names[0], description)
            for names, _, description in sections(help_text(mbc, "--help"))
            ["Commands"] if names[0] != "help"]


def write_man_pages(mbc, out_dir, cmds):
    os.makedirs(out_dir, exist_ok=True)
    see_also = os.path.join(out_dir, "see_also.h2m")
    pages = [f"mbc-{name}(1)" for name, _ in cmds]
    with open(see_also, "w") as f:
        f.write("[SEE ALSO]\n" + ", ".join(pages) + "\n")
    common = ["help2man", "--no-info", "--include", see_also]
    subprocess.run(common + [
        "--name", "compile and run FANUC Custom Macro B programs",
        "--output", os.path.join(out_dir, "mbc.1"), mbc], check=True)
    for name, description in cmds:
        page = os.path.join(out_dir, f"mbc-{name}.1")
        subprocess.run(common + [
            "--name", description[0].lower() + description[1:],
            "--help-option", f"{name} --help",
            "--output", page, mbc], check=True)
        # help2man names the page after the program: the title and the
        # NAME line become the command's (git's pages are named so).
        with open(page) as f:
            text = f.read()
        text = text.replace(".TH MBC ", f".TH MBC-{name.upper()} ", 1)
        text = text.replace("\nmbc \\- ", f"\nmbc-{name} \\- ", 1)
        with open(page, "w") as f:
            f.write(text)
    os.remove(see_also)


COMPLETION = """\
# bash completion of mbc, written from its help by tools/command_docs.py.
_mbc() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} prev=${{COMP_WORDS[COMP_CWORD-1]}}
  local commands="{commands} help"
  if [ "$COMP_CWORD" -eq 1 ]; then
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi
  local options=""
  case ${{COMP_WORDS[1]}} in
{options}
    help)
      [ "$COMP_CWORD" -eq 2 ] && COMPREPLY=($(compgen -W "$commands" -- "$cur"))
      return ;;
    *) return ;;
  esac
  case $prev in
{values}
  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -- "$cur"))
  fi
}}
complete -o filenames -F _mbc mbc
"""


def write_completion(mbc, path, cmds):
    options, choices, files = [], {}, set()
    for name, _ in cmds:
        names = []
        for group, entries in sections(help_text(mbc, name, "--help")).items():
            if group == "Arguments":
                continue
            for opt_names, value, _ in entries:
                names += [n.split("[")[0] for n in opt_names]
                if "|" in value and not value.startswith("O"):
                    for n in opt_names:
                        choices[n] = value.replace("|", " ")
                elif value in ("PATH", "DIR", "TABLE.csv"):
                    files.update(opt_names)
        options.append(f"    {name}) options=\"{' '.join(names)}\" ;;")
    values = [f"    {n}) COMPREPLY=($(compgen -W \"{w}\" -- \"$cur\")); "
              "return ;;" for n, w in sorted(choices.items())]
    if files:
        values.append(f"    {'|'.join(sorted(files))}) "
                      "COMPREPLY=($(compgen -f -- \"$cur\")); return ;;")
    text = COMPLETION.format(commands=" ".join(n for n, _ in cmds),
                             options="\n".join(options),
                             values="\n".join(values))
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("mbc")
    parser.add_argument("--man", required=True)
    parser.add_argument("--completion", required=True)
    args = parser.parse_args()
    cmds = commands(args.mbc)
    if not cmds:
        sys.exit("command_docs.py: no commands in mbc --help")
    write_man_pages(args.mbc, args.man, cmds)
    write_completion(args.mbc, args.completion, cmds)


if __name__ == "__main__":
    main()
