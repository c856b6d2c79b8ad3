// Meshes of the sliding example (sliding_cpp.cpp): a half disk on a block, 4-node
// quadrilaterals only, graded toward the contact, in the arrays hycon_model_new takes.
//
// Block: [-W, W] x [-D, 0], a tensor-product grid: element size h over the strip of x where the
// contact travels (and h at the top face), growing geometrically (ratio q, capped at h_max)
// toward the sides and the bottom.
//
// Half disk: radius R, centre (0, R), lowest point at the origin, flat top face y = R. An O-grid:
// a core rectangle [-c, c] x [R - c, R] and a band between it and the arc whose lines are rays
// from the centre (so the band's elements are polar cells); the arc is divided with size h for
// |x| <= fine (the contact zone on the disk) and graded beyond, the rays with size h at the arc
// and graded inward.
//
// Every element is listed counter-clockwise. Contact polylines run with their body on the left:
// the block's top right to left, the disk's arc left to right.
#ifndef HYCON_SLIDING_MESH_HPP
#define HYCON_SLIDING_MESH_HPP

#include <cmath>
#include <cstddef>
#include <vector>

namespace sliding {

// Nodes, elements (compressed) and per-element materials, as hycon_model_new takes them.
struct Mesh {
    std::vector<double> coords;           // x0 y0 x1 y1 ...
    std::vector<std::size_t> offsets{0};  // element e: nodes[offsets[e] .. offsets[e + 1]]
    std::vector<std::size_t> nodes;
    std::vector<std::size_t> materials;  // per element

    std::size_t node_count() const { return coords.size() / 2; }
    std::size_t element_count() const { return offsets.size() - 1; }
    double x(std::size_t node) const { return coords[2 * node]; }
    double y(std::size_t node) const { return coords[2 * node + 1]; }

    std::size_t add_node(double x, double y) {
        coords.push_back(x);
        coords.push_back(y);
        return node_count() - 1;
    }
    // A quadrilateral, nodes counter-clockwise.
    void add_quad(std::size_t a, std::size_t b, std::size_t c, std::size_t d,
                  std::size_t material) {
        nodes.insert(nodes.end(), {a, b, c, d});
        offsets.push_back(nodes.size());
        materials.push_back(material);
    }
};

// Steps from 0 to `length`: first `h0`, growing by `q`, capped at `h_max`, then all scaled so
// that they end exactly at `length`. Returns the positions (0 first, `length` last).
inline std::vector<double> graded(double length, double h0, double q, double h_max) {
    std::vector<double> steps;
    double sum = 0.0, h = h0;
    while (sum < length) {
        steps.push_back(h);
        sum += h;
        h = std::fmin(h * q, h_max);
    }
    if (steps.size() > 1 && sum - length > 0.5 * steps.back()) {  // drop a mostly-outside step
        sum -= steps.back();
        steps.pop_back();
    }
    std::vector<double> positions{0.0};
    double at = 0.0;
    for (double s : steps) {
        at += s * length / sum;
        positions.push_back(at);
    }
    positions.back() = length;
    return positions;
}

// Positions from `lo` to `hi`: uniform size h on [f0, f1] (f1 - f0 a multiple of h), graded
// (q, h_max) outward to lo and hi.
inline std::vector<double> graded_line(double lo, double f0, double f1, double hi, double h,
                                       double q, double h_max) {
    std::vector<double> out;
    const std::vector<double> left = graded(f0 - lo, h * q, q, h_max);
    for (std::size_t k = left.size(); k-- > 1;) out.push_back(f0 - left[k]);
    const auto fine = static_cast<std::size_t>(std::lround((f1 - f0) / h));
    for (std::size_t k = 0; k < fine; ++k) out.push_back(f0 + double(k) * (f1 - f0) / double(fine));
    for (double p : graded(hi - f1, h * q, q, h_max)) out.push_back(f1 + p);
    return out;
}

// The block and what the example needs of it.
struct Block {
    std::vector<std::size_t> bottom;  // fixed
    std::vector<std::size_t> top;     // the top face, right to left (body on the left)
};

// Add the block [-w, w] x [-depth, 0] to `mesh`; size h on x in [f0, f1] and at y = 0.
inline Block add_block(Mesh &mesh, double w, double depth, double f0, double f1, double h,
                       double q, double h_max, std::size_t material) {
    const std::vector<double> xs = graded_line(-w, f0, f1, w, h, q, h_max);
    std::vector<double> ys;
    const std::vector<double> down = graded(depth, h, q, h_max);
    for (std::size_t k = down.size(); k-- > 0;) ys.push_back(-down[k]);  // -depth .. 0
    const std::size_t nx = xs.size(), ny = ys.size(), first = mesh.node_count();
    auto id = [&](std::size_t i, std::size_t j) { return first + j * nx + i; };
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) mesh.add_node(xs[i], ys[j]);
    for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i)
            mesh.add_quad(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1), material);
    Block block;
    for (std::size_t i = 0; i < nx; ++i) block.bottom.push_back(id(i, 0));
    for (std::size_t i = nx; i-- > 0;) block.top.push_back(id(i, ny - 1));
    return block;
}

// The half disk and what the example needs of it.
struct Disk {
    std::vector<std::size_t> top;  // the flat top face y = R (tied to the plate)
    std::vector<std::size_t> arc;  // the arc, left to right (body on the left)
};

// Add the lower half disk of radius r (centre (0, r)) to `mesh`: size h on the arc where
// |x| <= fine, graded (q, h_max) beyond and inward; core half-width c = 0.45 r.
inline Disk add_half_disk(Mesh &mesh, double r, double fine, double h, double q, double h_max,
                          std::size_t material) {
    const double pi = std::acos(-1.0), c = 0.45 * r;
    // ray angles phi from the downward vertical: -pi/2 (left end of the top face) .. pi/2
    const double phi_fine = std::ceil(std::asin(fine / r) * r / h) * h / r;  // whole steps h / r
    const std::vector<double> bottom =
        graded_line(-pi / 4.0, -phi_fine, phi_fine, pi / 4.0, h / r, q, h_max / r);
    const double last = bottom[1] - bottom[0];  // the coarsest arc step of the bottom part
    const auto m = static_cast<std::size_t>(std::fmax(2.0, std::ceil(pi / 4.0 / last)));
    std::vector<double> phi;
    for (std::size_t k = 0; k < m; ++k) phi.push_back(-pi / 2.0 + double(k) * pi / 4.0 / double(m));
    phi.insert(phi.end(), bottom.begin(), bottom.end());
    for (std::size_t k = 1; k <= m; ++k) phi.push_back(pi / 4.0 + double(k) * pi / 4.0 / double(m));
    const std::size_t n_rays = phi.size(), n_bottom = bottom.size() - 1;
    // radial parameter t from the arc (0) to the core boundary (1), size h at the arc where the
    // ray is longest (r - c)
    const std::vector<double> t = graded(1.0, h / (r - c), q, h_max / (r - c));
    const std::size_t layers = t.size() - 1, first = mesh.node_count();
    auto band = [&](std::size_t i, std::size_t j) { return first + i * (layers + 1) + j; };
    for (std::size_t i = 0; i < n_rays; ++i) {
        const double s = std::sin(phi[i]), co = std::cos(phi[i]);
        const double ax = r * s, ay = r - r * co;  // on the arc
        const double reach = std::fabs(phi[i]) <= pi / 4.0 ? c / co : c / std::fabs(s);
        const double ix = reach * s, iy = r - reach * co;  // on the core's boundary
        for (std::size_t j = 0; j <= layers; ++j) {
            const bool end = i == 0 || i + 1 == n_rays;  // on the top face: exactly y = r
            mesh.add_node(ax + t[j] * (ix - ax), end ? r : ay + t[j] * (iy - ay));
        }
    }
    for (std::size_t i = 0; i + 1 < n_rays; ++i)
        for (std::size_t j = 0; j < layers; ++j)
            mesh.add_quad(band(i, j), band(i + 1, j), band(i + 1, j + 1), band(i, j + 1), material);
    // the core: columns at the bottom rays' x, rows at the left rays' y
    std::vector<std::size_t> core((n_bottom + 1) * (m + 1));
    auto at = [&](std::size_t ii, std::size_t k) -> std::size_t & {
        return core[k * (n_bottom + 1) + ii];
    };
    for (std::size_t k = 0; k <= m; ++k) {
        for (std::size_t ii = 0; ii <= n_bottom; ++ii) {
            if (k == 0)
                at(ii, k) = band(m + ii, layers);
            else if (ii == 0)
                at(ii, k) = band(m - k, layers);
            else if (ii == n_bottom)
                at(ii, k) = band(m + n_bottom + k, layers);
            else
                at(ii, k) = mesh.add_node(mesh.x(band(m + ii, layers)),
                                          k == m ? r : mesh.y(band(m - k, layers)));
        }
    }
    for (std::size_t k = 0; k < m; ++k)
        for (std::size_t ii = 0; ii < n_bottom; ++ii)
            mesh.add_quad(at(ii, k), at(ii + 1, k), at(ii + 1, k + 1), at(ii, k + 1), material);
    Disk disk;
    for (std::size_t j = 0; j <= layers; ++j) disk.top.push_back(band(0, j));
    for (std::size_t ii = 1; ii < n_bottom; ++ii) disk.top.push_back(at(ii, m));
    for (std::size_t j = 0; j <= layers; ++j) disk.top.push_back(band(n_rays - 1, j));
    for (std::size_t i = 0; i < n_rays; ++i) disk.arc.push_back(band(i, 0));
    return disk;
}

}  // namespace sliding

#endif  // HYCON_SLIDING_MESH_HPP
