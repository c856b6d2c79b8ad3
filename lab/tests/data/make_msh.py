#!/usr/bin/env python3
"""Writes the MSH 4.1 ASCII fixtures of the scene tests (Gmsh is not needed to run them).

The meshes are structured quadrilateral grids of rectangles, written the way Gmsh writes a
recombined mesh: $PhysicalNames, $Entities (one entity per physical group), $Nodes, $Elements.
Run from this folder: python3 make_msh.py . ../../../examples/scenes/two_punches
../../../examples/scenes/rounded_punch (it rewrites every .msh it owns;
examples/scenes/press/press.msh and press_slide/press.msh are press.msh).

Options per body exercise the reader's normalisation: `cw` writes its quadrilaterals clockwise,
`reverse` writes a boundary curve against the body's counter-clockwise direction (Gmsh's curve
direction is arbitrary), `tri` splits the body's quads into triangles (to be rejected).
"""
import sys


def rect(x0, y0, w, h, nx, ny, bottom=None):
    """A structured grid; `bottom(x)` lifts the bottom edge (the rows follow linearly)."""
    def y(x, j):
        b = y0 + (bottom(x) if bottom else 0.0)
        return b + (y0 + h - b) * j / ny
    nodes = [(x0 + w * i / nx, y(x0 + w * i / nx, j)) for j in range(ny + 1) for i in range(nx + 1)]
    quads = [(j * (nx + 1) + i, j * (nx + 1) + i + 1, (j + 1) * (nx + 1) + i + 1,
              (j + 1) * (nx + 1) + i) for j in range(ny) for i in range(nx)]
    # boundary edges, counter-clockwise around the body
    bottom = [(i, i + 1) for i in range(nx)]
    right = [(j * (nx + 1) + nx, (j + 1) * (nx + 1) + nx) for j in range(ny)]
    top = [((ny) * (nx + 1) + i + 1, ny * (nx + 1) + i) for i in reversed(range(nx))]
    left = [((j + 1) * (nx + 1), j * (nx + 1)) for j in reversed(range(ny))]
    return nodes, quads, {"bottom": bottom, "right": right, "top": top, "left": left}


def write(path, bodies, extra_points=()):
    """bodies: list of dicts name, rect args, curves {side: group name}, options."""
    nodes, surf, curves, points = [], [], [], []
    for b in bodies:
        off = len(nodes)
        n, q, sides = rect(*b["rect"], bottom=b.get("bottom"))
        nodes += n
        if b.get("cw"):
            q = [(a, d, c, bb) for (a, bb, c, d) in q]
        elems = [tuple(v + off for v in e) for e in q]
        if b.get("tri"):
            surf.append((b["name"], "tri", [t for (a, bb, c, d) in elems for t in ((a, bb, c), (a, c, d))]))
        else:
            surf.append((b["name"], "quad", elems))
        for side, group in b.get("curves", {}).items():
            segs = [(p + off, r + off) for (p, r) in sides[side]]
            if group in b.get("reverse", ()):
                segs = [(r, p) for (p, r) in reversed(segs)]
            curves.append((group, segs))
        for group, (i, j) in b.get("points", {}).items():
            nx = b["rect"][4]
            points.append((group, off + j * (nx + 1) + i))
    for group, idx in extra_points:
        points.append((group, idx))
    groups = [(2, s[0]) for s in surf] + [(1, c[0]) for c in curves] + [(0, p[0]) for p in points]
    phys = {g: k + 1 for k, g in enumerate(groups)}
    out = ["$MeshFormat", "4.1 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(groups))]
    out += [f'{d} {phys[(d, n)]} "{n}"' for (d, n) in groups]
    out += ["$EndPhysicalNames", "$Entities", f"{len(points)} {len(curves)} {len(surf)} 0"]
    for k, (g, i) in enumerate(points):
        x, y = nodes[i]
        out.append(f"{k + 1} {x} {y} 0 1 {phys[(0, g)]}")
    for k, (g, _) in enumerate(curves):
        out.append(f"{k + 1} 0 0 0 1 1 0 1 {phys[(1, g)]} 0")
    for k, (g, _, _) in enumerate(surf):
        out.append(f"{k + 1} 0 0 0 1 1 0 1 {phys[(2, g)]} 0")
    out += ["$EndEntities", "$Nodes", f"1 {len(nodes)} 1 {len(nodes)}", f"2 1 0 {len(nodes)}"]
    out += [str(i + 1) for i in range(len(nodes))]
    out += [f"{x:.17g} {y:.17g} 0" for (x, y) in nodes]
    out.append("$EndNodes")
    blocks = [(0, k + 1, 15, [(i,)]) for k, (_, i) in enumerate(points)]
    blocks += [(1, k + 1, 1, segs) for k, (_, segs) in enumerate(curves)]
    blocks += [(2, k + 1, 2 if kind == "tri" else 3, el) for k, (_, kind, el) in enumerate(surf)]
    total = sum(len(b[3]) for b in blocks)
    out += ["$Elements", f"{len(blocks)} {total} 1 {total}"]
    tag = 1
    for d, ent, kind, els in blocks:
        out.append(f"{d} {ent} {kind} {len(els)}")
        for e in els:
            out.append(" ".join(str(v) for v in [tag] + [i + 1 for i in e]))
            tag += 1
    out.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def press(cw=False, reverse=(), tri=False, nx=16, ny=4):
    """The two-block press: a base [0, 4] x [-1, 0] and a punch [1, 3] x [0, 1] on it."""
    return [
        {"name": "base", "rect": (0.0, -1.0, 4.0, 1.0, nx, ny), "cw": cw, "tri": tri,
         "curves": {"top": "base_top", "bottom": "base_bottom"}, "reverse": reverse},
        {"name": "punch", "rect": (1.0, 0.0, 2.0, 1.0, nx // 2 + 1, ny),
         "curves": {"bottom": "punch_bottom", "top": "punch_top", "left": "punch_left"},
         "reverse": reverse, "points": {"punch_corner": (0, 0)}},
    ]


def two_punches(nx=24, ny=4):
    """Three bodies, two contact pairs: two punches of different heights on one base [0, 6]."""
    return [
        {"name": "base", "rect": (0.0, -1.0, 6.0, 1.0, nx, ny),
         "curves": {"top": "base_top", "bottom": "base_bottom"}},
        {"name": "left_punch", "rect": (0.5, 0.0, 2.0, 1.0, 9, ny),
         "curves": {"bottom": "left_bottom", "top": "left_top"}},
        {"name": "right_punch", "rect": (3.5, 0.0, 2.0, 0.5, 7, 2),
         "curves": {"bottom": "right_bottom", "top": "right_top"}},
    ]


def rounded_punch(r=0.3):
    """A flat punch [1, 3] x [0, 1] whose bottom corners are rounded with radius r, on a base."""
    import math

    def lift(x):
        d = max(1.0 + r - x, x - (3.0 - r), 0.0)
        return r - math.sqrt(max(r * r - d * d, 0.0))
    return [
        {"name": "base", "rect": (0.0, -1.0, 4.0, 1.0, 40, 8),
         "curves": {"top": "base_top", "bottom": "base_bottom"}},
        {"name": "punch", "rect": (1.0, 0.0, 2.0, 1.0, 21, 8), "bottom": lift,
         "curves": {"bottom": "punch_bottom", "top": "punch_top"}},
    ]


if __name__ == "__main__":
    target = sys.argv[1] if len(sys.argv) > 1 else "."
    write(f"{target}/press.msh", press())
    write(f"{target}/press_cw.msh", press(cw=True, reverse=("base_top", "punch_bottom")))
    write(f"{target}/press_tri.msh", press(tri=True))
    if len(sys.argv) > 2:
        write(f"{sys.argv[2]}/two_punches.msh", two_punches())
    if len(sys.argv) > 3:
        write(f"{sys.argv[3]}/rounded_punch.msh", rounded_punch())
