#!/usr/bin/env python3
"""Compare two JSON summaries of `hycon contact --json` (issue 41's gate).

Every number must agree within `--relative` (default 1e-12) of the largest |value| of its
quantity over both files; integers (iteration counts, sizes), strings (states, names) and
booleans must be equal; keys naming timings are skipped. A quantity is a key path with the
array indices taken out, within one example (so `examples[2].increments[].nodes[].tn` is one
quantity): its largest |value| is the scale of its round-off.

Usage: scripts/compare_summary.py BASE.json NEW.json [--relative 1e-12]
Exit status 0 when they agree, 1 with the differences listed otherwise.
"""
import argparse
import json
import re
import sys

TIMING = re.compile(r"(second|timing|time|elapsed|_s$|_ms$)", re.IGNORECASE)


def indexed(value, path=()):
    if isinstance(value, dict):
        for key, v in value.items():
            yield from indexed(v, path + (key,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from indexed(v, path + (f"[{i}]",))
    else:
        yield path, value


def quantity(full):
    """The quantity of a full path: indices out, except the example's."""
    out = []
    for i, part in enumerate(full):
        if part.startswith("[") and not (i > 0 and full[i - 1] == "examples"):
            out.append("[]")
        else:
            out.append(part)
    return tuple(out)


def skipped(full):
    return any(TIMING.search(p) for p in full if not p.startswith("["))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("base")
    ap.add_argument("new")
    ap.add_argument("--relative", type=float, default=1e-12)
    args = ap.parse_args()
    a = dict(indexed(json.load(open(args.base))))
    b = dict(indexed(json.load(open(args.new))))
    problems = []
    if a.keys() != b.keys():
        for k in sorted(a.keys() ^ b.keys()):
            if not skipped(k):
                problems.append(f"only in {'base' if k in a else 'new'}: {'.'.join(k)}")
    scale = {}
    for d in (a, b):
        for k, v in d.items():
            if isinstance(v, float) and not skipped(k):
                q = quantity(k)
                scale[q] = max(scale.get(q, 0.0), abs(v) if v == v else 0.0)
    worst = {}
    compared = 0
    for k in sorted(a.keys() & b.keys()):
        if skipped(k):
            continue
        x, y = a[k], b[k]
        compared += 1
        if isinstance(x, float) or isinstance(y, float):
            if isinstance(x, bool) or isinstance(y, bool) or x is None or y is None:
                if x != y:
                    problems.append(f"{'.'.join(k)}: {x!r} != {y!r}")
                continue
            x, y = float(x), float(y)
            if x != x or y != y:
                if not (x != x and y != y):
                    problems.append(f"{'.'.join(k)}: {x!r} != {y!r}")
                continue
            q = quantity(k)
            d = abs(x - y)
            limit = args.relative * scale.get(q, 0.0)
            worst[q] = max(worst.get(q, 0.0), d / scale[q] if scale.get(q) else d)
            if d > limit and x != y:
                problems.append(f"{'.'.join(k)}: {x!r} vs {y!r} (|diff| {d:.3e} > {limit:.3e})")
        elif x != y:
            problems.append(f"{'.'.join(k)}: {x!r} != {y!r}")
    differing = {q: w for q, w in worst.items() if w > 0}
    print(f"{compared} values compared, {len(scale)} float quantities; "
          f"{len(differing)} quantities not bit-identical; "
          f"largest relative difference {max(worst.values(), default=0.0):.3e}")
    for p in problems[:50]:
        print("  " + p)
    if len(problems) > 50:
        print(f"  ... {len(problems) - 50} more")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
