#!/usr/bin/env python3
"""The folders of src/ and the includes between them: checks that data flows one way and draws it.

Each folder has a level; a file may include only folders of a lower level (and its own). The
levels follow the data flow: model -> motor -> sim -> eval -> ga -> search -> record -> report -> run -> app, and
sim -> render -> movie -> replay, image -> encode -> movie; adapt (trial and error over a repertoire)
sits above search beside record.

  scripts/layers.py --check        exit 1, naming file:line, on any include that goes up
  scripts/layers.py --dot          the folder graph in Graphviz's language
  scripts/layers.py --png FILE     the same drawn (needs Graphviz's `dot`; Debian: graphviz)
"""
import argparse
import collections
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
SRC = ROOT / "src"

LEVEL = {
    "util": 0,
    "image": 1, "simd": 1, "model": 1,
    "encode": 2, "motor": 2,
    "sim": 3,
    "eval": 4, "render": 4,
    "ga": 5, "movie": 5,
    "bench": 6, "study": 6, "search": 6, "replay": 6,
    "adapt": 7,
    "record": 7,
    "report": 8,
    "run": 9,
    "app": 10,
    "python": 11,
}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/')


def includes():
    """(from_folder, to_folder) -> [file:line, ...] for every include across folders."""
    edges = collections.defaultdict(list)
    for path in sorted(SRC.rglob("*")):
        if path.suffix not in (".h", ".cc"):
            continue
        folder = path.relative_to(SRC).parts[0]
        for number, line in enumerate(path.read_text().splitlines(), 1):
            m = INCLUDE.match(line)
            if m and m.group(1) != folder:
                edges[(folder, m.group(1))].append(f"{path.relative_to(ROOT)}:{number}")
    return edges


def check(edges):
    bad = 0
    for folder in sorted({f for e in edges for f in e}):
        if folder not in LEVEL:
            print(f"layers: src/{folder} has no level; add it to LEVEL in scripts/layers.py")
            bad += 1
    for (a, b), where in sorted(edges.items()):
        if a in LEVEL and b in LEVEL and LEVEL[b] >= LEVEL[a]:
            for w in where:
                print(f"layers: {w}: src/{a} (level {LEVEL[a]}) includes src/{b} "
                      f"(level {LEVEL[b]}): an arrow up the data flow")
            bad += len(where)
    if not bad:
        print(f"layers: {len(LEVEL)} folders, {len(edges)} arrows, none up the data flow")
    return bad == 0


def dot(edges):
    lines = ["digraph hexgait {", "  rankdir=BT; node [shape=box, style=rounded, "
             "fontname=Helvetica]; edge [color=gray40];"]
    for level in sorted(set(LEVEL.values())):
        names = " ".join(f'"{f}"' for f in sorted(LEVEL) if LEVEL[f] == level)
        lines.append(f"  {{ rank=same; {names} }}")
    # Every arrow points up the page (rankdir=BT); the label counts the includes. Arrows into
    # util, which everything uses, are drawn faint so the data flow stands out.
    for (a, b), where in sorted(edges.items()):
        style = 'color=gray80, arrowsize=0.5' if b == "util" else f'label="{len(where)}", fontsize=9'
        lines.append(f'  "{a}" -> "{b}" [{style}];')
    lines.append("}")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--check", action="store_true")
    group.add_argument("--dot", action="store_true")
    group.add_argument("--png", metavar="FILE")
    args = parser.parse_args()
    edges = includes()
    if args.check:
        return 0 if check(edges) else 1
    if args.dot:
        sys.stdout.write(dot(edges))
        return 0
    subprocess.run(["dot", "-Tpng", "-Gdpi=110", "-o", args.png], input=dot(edges), text=True,
                   check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
