#!/usr/bin/env python3
"""The layering rules of the source tree, checked on every source file.

Each folder may include the project headers of the folders listed for it and
nothing else; no Qt header appears outside editor/. The build enforces the
library seams too (each library exposes only its own include folder), but a
rule written once here also covers what the build would let through, such as
a model header that is never compiled on its own or an editor command that
includes a dock.

Usage: check_layers.py SOURCE_ROOT. Prints every violation as
`file:line: message` and exits 1 if there is any.
"""
import pathlib
import re
import sys

# Folder (relative to the source root) -> project folders it may include.
# The most specific folder wins.
ALLOWED = {
    "model": {"model"},
    "solver": {"model", "solver"},
    "output": {"model", "solver", "output"},
    "importer": {"model", "solver", "importer"},
    "cli": {"model", "solver", "output", "importer", "cli"},
    "editor": {"model", "solver", "output", "importer", "editor"},
    # Undo commands change the scene through the model's edit functions and
    # know the document, nothing else of the editor.
    "editor/document": {"model", "editor/document"},
}
QT_ALLOWED = ("editor",)
PROJECT_FOLDERS = ("model", "solver", "output", "importer", "cli", "editor", "tests")

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^">]+)[">]')
# <QString>, <QtWidgets/QWidget>, <QtCore>: Qt names its headers after its classes and modules.
QT_HEADER = re.compile(r"^Qt?[A-Z][A-Za-z0-9]*(/|$)")


def rule_for(relative: str):
    best = None
    for folder in ALLOWED:
        if relative == folder or relative.startswith(folder + "/"):
            if best is None or len(folder) > len(best):
                best = folder
    return best


def project_target(header: str):
    for folder in PROJECT_FOLDERS:
        if header.startswith(folder + "/"):
            return header
    return None


def check(root: pathlib.Path):
    problems = []
    files = 0
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".h", ".cpp") or not path.is_file():
            continue
        relative = path.relative_to(root).as_posix()
        folder = rule_for(relative)
        if folder is None:
            continue  # tests, scripts, the build tree
        files += 1
        allowed = ALLOWED[folder]
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            match = INCLUDE.match(line)
            if not match:
                continue
            header = match.group(2)
            where = f"{relative}:{number}"
            if QT_HEADER.match(header):
                if not relative.startswith(QT_ALLOWED):
                    problems.append(f"{where}: Qt header <{header}> outside editor/")
                continue
            target = project_target(header)
            if target is None:
                if match.group(1) == '"':
                    problems.append(f'{where}: "{header}" is not a project path (write "folder/file.h")')
                continue
            if not any(target.startswith(a + "/") for a in allowed):
                problems.append(f"{where}: {folder}/ may not include {header}")
    return files, problems


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    files, problems = check(root)
    for p in problems:
        print(p)
    if files == 0:
        print("no source files found below", root)
        return 1
    print(f"{files} files checked, {len(problems)} layering violations")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
