#!/usr/bin/env python3
"""Checks that the folder-level include graph of the tree has no cycle (docs/design.md, "Layout").

Every folder is a layer: a file may include files of its own folder and of folders below it,
never of a folder that (through any chain of includes) includes it back. The check reads every
`#include "..."` line of the C++ and GLSL sources, resolves the path as the build does, and
draws an edge from the including file's folder to the included file's folder. A strongly
connected set of two or more folders is a cycle: the check names it, with the include lines
that close it, and exits 1.

Resolution, in the order the compilers search for a quoted include:
  1. the including file's own folder (same-folder includes, and the shaders'
     `#include "../common/shared/x.h"`);
  2. the include roots the CMake targets add: the repository root (`vulkan_rt/device/x.h`),
     `common/` (`shared/x.h`, `scene/x.h`), `shaders/` (glslang's -I) and `tests/`
     (`support/x.h`).
An include that resolves nowhere in the tree (the generated SPIR-V headers) draws no edge.

Usage:
  scripts/check_layers.py [--root DIR] [--graph]   exit 0: no cycle; 1: cycles (named)
  scripts/check_layers.py --self-test              checks the checker on small temporary trees
"""

import argparse
import collections
import os
import re
import subprocess
import sys
import tempfile

SOURCE_EXTENSIONS = (".h", ".hpp", ".cpp", ".c", ".glsl", ".comp", ".rgen", ".rchit", ".rmiss",
                     ".rint")
# Searched after the including file's folder, as the targets' include directories are.
INCLUDE_ROOTS = (".", "common", "shaders", "tests")
INCLUDE_LINE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def is_skipped_dir(root, rel_dir, name):
    """Hidden folders, build trees (the presets' build*/ and any folder holding a CMake cache)."""
    if name.startswith(".") or name.startswith("build"):
        return True
    return os.path.exists(os.path.join(root, rel_dir, name, "CMakeCache.txt"))


def source_files(root):
    """Repository-relative paths of the sources, with '/' separators, sorted."""
    files = []
    for dirpath, dirnames, filenames in os.walk(root):
        rel_dir = os.path.relpath(dirpath, root)
        dirnames[:] = sorted(d for d in dirnames if not is_skipped_dir(root, rel_dir, d))
        for name in filenames:
            if name.endswith(SOURCE_EXTENSIONS):
                files.append(os.path.normpath(os.path.join(rel_dir, name)).replace(os.sep, "/"))
    return sorted(files)


def folder_of(rel_path):
    return os.path.dirname(rel_path) or "."


def resolve(root, including, target):
    """The repository-relative path that `#include "target"` in `including` names, or None."""
    bases = [folder_of(including)] + list(INCLUDE_ROOTS)
    for base in bases:
        candidate = os.path.normpath(os.path.join(base, target)).replace(os.sep, "/")
        if candidate == ".." or candidate.startswith("../"):
            continue  # outside the tree
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def include_edges(root):
    """{(from_folder, to_folder): [(file, line, included file), ...]}, and the unresolved
    includes as (file, line, name)."""
    edges = collections.defaultdict(list)
    unresolved = []
    for rel in source_files(root):
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                match = INCLUDE_LINE.match(line)
                if not match:
                    continue
                target = resolve(root, rel, match.group(1))
                if target is None:
                    unresolved.append((rel, number, match.group(1)))
                    continue
                a, b = folder_of(rel), folder_of(target)
                if a != b:
                    edges[(a, b)].append((rel, number, target))
    return edges, unresolved


def strongly_connected(nodes, successors):
    """Tarjan's strongly connected components, iteratively; each as a sorted list."""
    index, low, on_stack, stack, components = {}, {}, set(), [], []
    counter = 0
    for start in nodes:
        if start in index:
            continue
        work = [(start, iter(successors.get(start, ())))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            advanced = False
            for child in children:
                if child not in index:
                    index[child] = low[child] = counter
                    counter += 1
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(successors.get(child, ()))))
                    advanced = True
                    break
                if child in on_stack:
                    low[node] = min(low[node], index[child])
            if advanced:
                continue
            work.pop()
            if work:
                parent = work[-1][0]
                low[parent] = min(low[parent], low[node])
            if low[node] == index[node]:
                component = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    component.append(member)
                    if member == node:
                        break
                components.append(sorted(component))
    return components


def shortest_cycle(start, members, successors):
    """A shortest cycle through `start` inside `members`, as a list of folders ending at start."""
    previous = {start: None}
    queue = collections.deque([start])
    while queue:
        node = queue.popleft()
        for child in sorted(successors.get(node, ())):
            if child not in members:
                continue
            if child == start:
                path = [node]
                while previous[path[-1]] is not None:
                    path.append(previous[path[-1]])
                return list(reversed(path)) + [start]
            if child not in previous:
                previous[child] = node
                queue.append(child)
    return [start]


def find_cycles(edges):
    """The folder sets that include each other, each with a shortest cycle through its first."""
    successors = collections.defaultdict(set)
    nodes = set()
    for a, b in edges:
        successors[a].add(b)
        nodes.update((a, b))
    cycles = []
    for component in strongly_connected(sorted(nodes), successors):
        if len(component) > 1:
            cycles.append((component, shortest_cycle(component[0], set(component), successors)))
    return cycles


def report(root, show_graph=False, out=sys.stdout):
    """Prints the result; returns the exit status (0: no cycle, 1: cycles)."""
    edges, unresolved = include_edges(root)
    folders = {f for edge in edges for f in edge}
    if show_graph:
        for (a, b), evidence in sorted(edges.items()):
            print(f"{a} -> {b}  ({len(evidence)} include(s), e.g. {evidence[0][0]}:"
                  f"{evidence[0][1]})", file=out)
        for rel, number, target in unresolved:
            print(f"unresolved (no edge): {rel}:{number}: \"{target}\"", file=out)
    cycles = find_cycles(edges)
    print(f"{len(folders)} folders, {len(edges)} folder edges, {len(cycles)} cycle(s)", file=out)
    for component, cycle in cycles:
        print(f"cycle among {len(component)} folders ({', '.join(component)}), e.g. "
              f"{' -> '.join(cycle)}", file=out)
        members = set(component)
        for (a, b), evidence in sorted(edges.items()):
            if a in members and b in members:
                rel, number, target = evidence[0]
                more = f" (+{len(evidence) - 1} more)" if len(evidence) > 1 else ""
                print(f"  {a} -> {b}: {rel}:{number} includes {target}{more}", file=out)
    return 1 if cycles else 0


def write_tree(root, files):
    for rel, text in files.items():
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)


def self_test():
    """The checker on small trees: it must pass an acyclic one and fail (exit 1, naming the
    folders) on cyclic ones, as a separate process so that the exit status is checked too."""
    acyclic = {
        "low/base.h": "#pragma once\n",
        "low/base.cpp": '#include "low/base.h"\n#include "base.h"\n',
        "mid/mid.h": '#include "low/base.h"\n#include "generated.spv.h"\n',
        "common/shared/math.h": "// shared\n",
        "common/scene/scene.h": '#include "shared/math.h"\n',
        "shaders/trace.comp": '#include "../common/shared/math.h"\n#include "hooks.glsl"\n',
        "shaders/hooks.glsl": '#include "scene_reads.glsl"\n',
        "shaders/scene_reads.glsl": "\n",
        "top/top.cpp": '#include "mid/mid.h"\n// #include "top/top.h" in a comment\n',
        # Build trees are not the source: this include would close a cycle if it were read.
        "build/low/gen.h": '#include "top/top.cpp"\n',
    }
    # (name, tree, expected exit status, words the output must hold, words it must not)
    cases = [
        ("acyclic tree", acyclic, 0,
         ["0 cycle(s)", "mid -> low", "top -> mid", "common/scene -> common/shared",
          "shaders -> common/shared", 'unresolved (no edge): mid/mid.h:2: "generated.spv.h"'],
         ["build", "low -> low", "top -> top"]),
        ("two folders including each other", dict(acyclic, **{
            "low/back.cpp": '#include "mid/mid.h"\n'}),
         1, ["1 cycle(s)", "low -> mid -> low", "low/back.cpp:1 includes mid/mid.h"], []),
        ("a cycle through the common/ include root", dict(acyclic, **{
            "common/shared/up.h": '#include "scene/scene.h"\n'}),
         1, ["common/scene -> common/shared -> common/scene"], []),
        ("a cycle through a shader's relative include", dict(acyclic, **{
            "common/shared/up.h": '#include "../../shaders/hooks.glsl"\n'}),
         1, ["common/shared -> shaders -> common/shared"], []),
        ("a longer cycle", dict(acyclic, **{
            "low/loop.glsl": '#include "top/top.cpp"\n'}),
         1, ["cycle among 3 folders (low, mid, top), e.g. low -> top -> mid -> low"], []),
    ]
    failures = 0
    for name, files, expected_status, wanted, unwanted in cases:
        with tempfile.TemporaryDirectory() as tmp:
            write_tree(tmp, files)
            run = subprocess.run(
                [sys.executable, os.path.abspath(__file__), "--root", tmp, "--graph"],
                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        problems = [f"missing {w!r}" for w in wanted if w not in run.stdout]
        problems += [f"unexpected {w!r}" for w in unwanted if w in run.stdout]
        if run.returncode != expected_status:
            problems.insert(0, f"exit {run.returncode}, expected {expected_status}")
        failures += bool(problems)
        print(f"{'FAIL' if problems else 'ok'}: {name}" + (": " + "; ".join(problems)
                                                          if problems else ""))
        if problems:
            print("    " + run.stdout.strip().replace("\n", "\n    "))
    return 1 if failures else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", default=os.path.dirname(os.path.dirname(os.path.abspath(
        __file__))), help="the tree to check (default: this script's repository)")
    parser.add_argument("--graph", action="store_true",
                        help="also print every folder edge and every unresolved include")
    parser.add_argument("--self-test", action="store_true",
                        help="check the checker on small temporary trees")
    args = parser.parse_args()
    if args.self_test:
        return self_test()
    return report(os.path.abspath(args.root), args.graph)


if __name__ == "__main__":
    sys.exit(main())
