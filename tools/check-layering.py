#!/usr/bin/env python3
"""Checks modeflow's module layering; exits 1 and lists every violation.

A module is a folder with a CMakeLists.txt that defines one library, executable or Python module. Its declared
dependencies are the modeflow_* targets it links (target_link_libraries, followed transitively).
The rules:
  1. every `#include "..."` of a repository file belongs to the including module itself or to a
     module it declares (so the build graph and the include graph agree);
  2. the declared module graph is acyclic;
  3. precompute modules depend on no engine module but engine/core, engine/format and
     engine/basis, and no
     engine module depends on precompute (tools/compose is where the two meet);
  4. engine/core depends on no other module;
  5. every test file under tests/ has its modeflow_test() line in tests/CMakeLists.txt, and its
     includes belong to the libraries that line links (rule 1, one test file at a time).
Run from anywhere: `tools/check-layering.py` (CI runs it from .ci/run).
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCANNED = ("engine", "precompute", "tools", "shaders", "tests")
SOURCE_EXTS = (".h", ".cpp")


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def strip_cmake_comments(text):
    return "\n".join(line.split("#", 1)[0] for line in text.splitlines())


def modules():
    """folder -> {'targets': set, 'links': set of modeflow_* names}"""
    found = {}
    for top in SCANNED:
        for folder, _, files in os.walk(os.path.join(ROOT, top)):
            if "CMakeLists.txt" not in files:
                continue
            text = strip_cmake_comments(read(os.path.join(folder, "CMakeLists.txt")))
            targets = set(re.findall(r"(?:add_library|add_executable|pybind11_add_module)\(\s*([\w-]+)", text))
            if not targets:
                continue
            links = set()
            for target, body in re.findall(r"target_link_libraries\(\s*([\w-]+)([^)]*)\)", text, re.S):
                if target in targets:
                    links |= set(re.findall(r"\b(modeflow_\w+)", body))
            rel = os.path.relpath(folder, ROOT)
            found[rel] = {"targets": targets, "links": links - targets}
    return found


def main():
    mods = modules()
    owner = {t: folder for folder, m in mods.items() for t in m["targets"]}
    problems = []

    direct = {}
    for folder, m in mods.items():
        deps = set()
        for name in m["links"]:
            if name in owner:
                deps.add(owner[name])
            elif name not in ("modeflow_cholmod",):  # imported system libraries
                problems.append(f"{folder}/CMakeLists.txt links {name}, which no module defines")
        direct[folder] = deps

    def closure(folder, seen=None):
        seen = set() if seen is None else seen
        for dep in direct.get(folder, ()):
            if dep not in seen:
                seen.add(dep)
                closure(dep, seen)
        return seen

    # Rule 2: acyclic.
    state = {}

    def visit(folder, path):
        state[folder] = "open"
        for dep in sorted(direct[folder]):
            if state.get(dep) == "open":
                cycle = path[path.index(dep):] + [dep] if dep in path else [folder, dep]
                problems.append("module cycle: " + " -> ".join(cycle))
            elif dep not in state:
                visit(dep, path + [dep])
        state[folder] = "done"

    for folder in sorted(direct):
        if folder not in state:
            visit(folder, [folder])

    # Rules 3 and 4.
    for folder, deps in sorted(direct.items()):
        for dep in sorted(deps):
            if folder.startswith("precompute") and dep.startswith("engine/") and dep not in (
                    "engine/core", "engine/format", "engine/basis"):
                problems.append(f"{folder} depends on {dep}: precompute may use only engine/core, engine/format "
                                "and engine/basis")
            if folder.startswith("engine/") and dep.startswith("precompute"):
                problems.append(f"{folder} depends on {dep}: the engine uses nothing of precompute "
                                "(tools/compose composes them)")
        if folder == "engine/core" and deps:
            problems.append(f"engine/core depends on {', '.join(sorted(deps))}: it must depend on nothing")

    # Rule 1: includes agree with the declared dependencies.
    def module_of(rel_file):
        folder = os.path.dirname(rel_file)
        while folder and folder not in mods:
            folder = os.path.dirname(folder)
        return folder or None

    include = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)

    def check_includes(rel, allowed, declarer):
        for header in include.findall(read(os.path.join(ROOT, rel))):
            if header.endswith(".spv.h"):
                target = "shaders"
            elif os.path.exists(os.path.join(ROOT, header)):
                target = module_of(header)
            else:
                continue  # beside the file, or generated
            if target is None:
                problems.append(f"{rel} includes {header}, which belongs to no module")
            elif target not in allowed:
                problems.append(f"{rel} includes {header} from {target}, which {declarer} does not declare")

    for folder in sorted(mods):
        allowed = closure(folder) | {folder}
        for name in sorted(os.listdir(os.path.join(ROOT, folder))):
            if name.endswith(SOURCE_EXTS):
                check_includes(os.path.join(folder, name), allowed, folder)

    # Rule 5: each test executable, from its line in tests/CMakeLists.txt.
    tests_cmake = strip_cmake_comments(read(os.path.join(ROOT, "tests", "CMakeLists.txt")))
    declared = {}
    for path, body in re.findall(r"modeflow_test\(\s*([\w/]+)([^)]*)\)", tests_cmake):
        declared[os.path.join("tests", path + ".cpp")] = set(re.findall(r"\b(modeflow_\w+)", body))
    for top, _, files in os.walk(os.path.join(ROOT, "tests")):
        for name in files:
            rel = os.path.relpath(os.path.join(top, name), ROOT)
            if name.endswith("Test.cpp") and rel not in declared:
                problems.append(f"{rel} has no modeflow_test() line in tests/CMakeLists.txt")
    for rel, links in sorted(declared.items()):
        if not os.path.exists(os.path.join(ROOT, rel)):
            problems.append(f"tests/CMakeLists.txt names {rel}, which does not exist")
            continue
        allowed = set()
        for name in links:
            if name not in owner:
                problems.append(f"tests/CMakeLists.txt links {name} to {rel}, which no module defines")
                continue
            allowed |= closure(owner[name]) | {owner[name]}
        check_includes(rel, allowed, "its modeflow_test() line")

    if problems:
        print("layering check failed:")
        for p in problems:
            print("  " + p)
        return 1
    print(f"layering check: {len(mods)} modules and {len(declared)} tests, includes agree with their declared "
          "dependencies")
    return 0


if __name__ == "__main__":
    sys.exit(main())
