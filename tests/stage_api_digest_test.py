#!/usr/bin/env python3
"""The signature block atop framework/render/stage_api.h against the headers it summarises.

    stage_api_digest_test.py FRAMEWORK

Students read that block instead of the headers, so each declaration in it must be one the
headers make: every function and member it lists (with the class qualifier dropped, a template's
parameter P read as Params) is found, with the same types, in the framework's headers (comments
out, whitespace runs as one space). Before checking, it plants a wrong signature in a copy of
the block and requires the check to catch it, so the test can fail. Exits 1 naming each entry
that is not found.
"""
import pathlib
import re
import sys


def flat(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    text = re.sub(r"\s+", " ", text)
    return re.sub(r"\s*([(),<>&*;{}=])\s*", r"\1", text).strip()


def digest_entries(stage_api):
    """The block's declarations: its indented code lines, a statement per entry."""
    block = stage_api.split("#pragma once")[0]
    entries, current = [], ""
    for line in block.splitlines():
        if not line.startswith("//   "):
            current = ""
            continue
        indent = len(line) - len(line.lstrip("/ ")) - 2
        code = re.sub(r"//.*$", "", line[5:]).strip()
        if not current and indent >= 7:  # a comment's wrapped line, not a declaration
            continue
        if not code or re.match(r"^[a-z]+\.[a-z]+:", code) or code.startswith("PATHWAY_TODO"):
            current = ""
            continue
        current = (current + " " + code).strip()
        if current.endswith((";", "{", "}")):
            entries.append(current)
            current = ""
    return entries


def declarations(entry):
    """The pieces of one entry to look for in the headers."""
    entry = entry.rstrip(";").strip()
    entry = re.sub(r"^template <typename IntegratorType> ", "", entry).replace("<P>", "<Params>")
    one_line = re.match(r"^((?:struct|class|enum class) \w+) \{(.*)\}$", entry)
    if one_line:  # struct Ray { Vec3 origin; ... }: the type, then each member
        head, body = one_line.groups()
        if head.startswith("enum"):
            return [entry]
        return [head] + [part.strip() for part in body.split(";") if part.strip()]
    if entry.endswith("{"):  # struct Frame {: the type
        return [entry[:-1].strip()]
    if entry.startswith("class ") or entry.startswith("struct "):  # class EyeLightIntegrator
        return [entry]
    entry = re.sub(r"\b\w+::(?=\w+\()", "", entry)  # FilmBlock::addSample( -> addSample(
    return [entry]


def found(piece, headers):
    # A member or function is declared where the piece is followed by what ends a declaration:
    # ; { = (a default) , (the next member) or the end of a type's name.
    if re.search(re.escape(flat(piece)) + r"(?=[;{=,:]|$| )", headers):
        return True
    members = re.match(r"^([\w:<>]+) (\w+(?:, \w+)+)$", piece)  # uint32_t mesh, triangle
    return bool(members) and all(
        found(members.group(1) + " " + name, headers) for name in members.group(2).split(", "))


def missing(entries, headers):
    problems = []
    for entry in entries:
        for piece in declarations(entry):
            if not found(piece, headers):
                problems.append(f"{piece!r} (from {entry!r})")
    return problems


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    framework = pathlib.Path(sys.argv[1])
    stage_api = (framework / "render" / "stage_api.h").read_text()
    # Comments are left out, so the block cannot find itself.
    headers = " ".join(flat(path.read_text()) for path in sorted(framework.rglob("*.h")))
    entries = digest_entries(stage_api)
    if len(entries) < 40:
        sys.exit(f"stage_api_digest_test: only {len(entries)} entries read from stage_api.h")
    planted = [e.replace("float next1D()", "float next1D(int)") for e in entries]
    if not missing(planted, headers):
        sys.exit("stage_api_digest_test: a planted wrong signature (next1D(int)) was not caught")
    problems = missing(entries, headers)
    for problem in problems:
        print("stage_api.h lists", problem, "but no framework header declares it")
    print(f"stage_api_digest_test: {len(entries)} entries, {len(problems)} not found")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
