#!/usr/bin/env python3
"""Compare two listings of `hycon bench presses --list FILE` (issue 41's gate).

Prints the count per outcome class (hycon's rules, and the paper's alone) in both, and every
press whose outcome or iteration count changed. Exit status 0 when the listings agree line for
line, 1 otherwise.

Usage: scripts/compare_presses.py BASE.tsv NEW.tsv
"""
import collections
import sys


def read(path):
    rows = {}
    for line in open(path):
        seed, index, outcome, iterations, paper, paper_iterations = line.rstrip("\n").split("\t")
        rows[(int(seed), int(index))] = (outcome, iterations, paper, paper_iterations)
    return rows


def main():
    base, new = read(sys.argv[1]), read(sys.argv[2])
    for name, column in [("hycon's rules", 0), ("the paper's rules alone", 2)]:
        print(f"{name}:")
        a = collections.Counter(r[column] for r in base.values())
        b = collections.Counter(r[column] for r in new.values())
        for cls in sorted(a.keys() | b.keys()):
            mark = "" if a[cls] == b[cls] else "   <- differs"
            print(f"  {a[cls]:6d} {b[cls]:6d}  {cls}{mark}")
    changed = [k for k in sorted(base.keys() | new.keys()) if base.get(k) != new.get(k)]
    print(f"{len(base)} / {len(new)} presses; {len(changed)} changed")
    for k in changed:
        print(f"  seed {k[0]} press {k[1]}: {base.get(k)} -> {new.get(k)}")
    sys.exit(1 if changed else 0)


if __name__ == "__main__":
    main()
