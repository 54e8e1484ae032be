#!/usr/bin/env python3
"""The folders of planet/ and engine/ are layers: each is a library, no two include each other (directly
or round a longer loop), and every include of another folder's header is covered by the library's
declared dependencies (direct or inherited), so a back-arrow fails here and not in review. A private
header (globe_private_headers) is included by its own folder's files alone, and never by a public
header: the installed (public) headers must compile without it.

Usage: layers_test.py SOURCE_DIR BUILD_DIR  (BUILD_DIR/layers.txt is written by cmake/Layers.cmake)
"""
import os
import re
import sys

INCLUDE = re.compile(r'\s*#\s*include\s+"(((?:planet|engine)/[^/"]+)/[^"]+)"')


def read_layers(path):
    """folder -> target, target -> direct globe dependencies and the private headers, from
    cmake/Layers.cmake's file."""
    folder_target, dependencies, private = {}, {}, set()
    with open(path) as f:
        for line in f:
            words = line.split()
            if words and words[0] == "private":
                private.update(words[1:])
            elif len(words) >= 2:
                folder_target[words[0]] = words[1]
                dependencies[words[1]] = words[2:]
    return folder_target, dependencies, private


def closure(target, dependencies):
    seen, stack = set(), list(dependencies.get(target, []))
    while stack:
        t = stack.pop()
        if t not in seen:
            seen.add(t)
            stack.extend(dependencies.get(t, []))
    return seen


def source_folders(src):
    """Each direct subfolder of planet/ and engine/ holding C++ files, with its files."""
    folders = {}
    for top in ("planet", "engine"):
        for name in sorted(os.listdir(os.path.join(src, top))):
            folder = os.path.join(top, name)
            path = os.path.join(src, folder)
            if not os.path.isdir(path):
                continue
            files = [os.path.join(root, f) for root, _, fs in os.walk(path) for f in fs if f.endswith((".h", ".cpp"))]
            if files:
                folders[folder] = sorted(files)
    return folders


def includes(src, folders):
    """(including folder, its file, line number, included header, the header's folder) for each
    include of a planet/ or engine/ header."""
    found = []
    for folder, files in folders.items():
        for path in files:
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if m:
                        found.append((folder, os.path.relpath(path, src), number, m.group(1), m.group(2)))
    return found


def include_edges(found):
    """(from folder, to folder) -> first 'file:line' that includes across them."""
    edges = {}
    for folder, path, number, _, to in found:
        if to != folder and (folder, to) not in edges:
            edges[(folder, to)] = f"{path}:{number}"
    return edges


def private_header_failures(found, private):
    failures = []
    for folder, path, number, header, to in found:
        if header not in private:
            continue
        if to != folder:
            failures.append(f"{path}:{number}: includes {header}, private to {to}/")
        elif path.endswith(".h") and path not in private:
            failures.append(f"{path}:{number}: a public header includes the private {header}")
    return failures


def find_cycle(nodes, successors):
    """A list of nodes round one cycle, or None."""
    state, stack = {}, []

    def visit(node):
        state[node] = "open"
        stack.append(node)
        for nxt in sorted(successors.get(node, ())):
            if state.get(nxt) == "open":
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        stack.pop()
        state[node] = "done"
        return None

    for node in sorted(nodes):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def main():
    src, build = sys.argv[1], sys.argv[2]
    folder_target, dependencies, private = read_layers(os.path.join(build, "layers.txt"))
    folders = source_folders(src)
    found = includes(src, folders)
    edges = include_edges(found)
    failures = private_header_failures(found, private)
    for folder in folders:
        if folder not in folder_target:
            failures.append(f"{folder}: not a library of its own (no globe_add_library in its CMakeLists.txt)")
    successors = {}
    for (a, b) in edges:
        successors.setdefault(a, set()).add(b)
    cycle = find_cycle(folders, successors)
    if cycle:
        steps = [f"{a} ({edges[(a, b)]})" for a, b in zip(cycle, cycle[1:])]
        failures.append("include cycle: " + " -> ".join(steps) + f" -> {cycle[-1]}")
    target_cycle = find_cycle(dependencies, {t: set(d) for t, d in dependencies.items()})
    if target_cycle:
        failures.append("link cycle: " + " -> ".join(target_cycle))
    for (a, b), where in sorted(edges.items()):
        if a in folder_target and b in folder_target:
            if folder_target[b] not in closure(folder_target[a], dependencies):
                failures.append(f"{where}: includes {b}/ but {folder_target[a]} does not link {folder_target[b]}")
    for failure in failures:
        print("FAIL:", failure)
    print(f"layers: {len(folders)} folders, {len(edges)} include edges, {len(private)} private headers, "
          f"{len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
