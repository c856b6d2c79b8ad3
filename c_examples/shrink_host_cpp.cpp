// The shrink fit of shrink_fit.c solved by a host code in C++17 through the host-assembly API:
// the host numbers its own equations, assembles its stiffness in CSR from
// hycon::element_stiffness with a HYCON_AXISYMMETRIC material (x = r, y = z, the full circle
// 2 pi r), describes the contact pair in its numbering with the analysis kind
// (Host::add_pair(..., HYCON_AXISYMMETRIC, 1.0)) and runs hycon's contact iteration.
//
// Two thick tubes (docs/validation.md, "Shrink fit of two tubes": a = 0.5, b = 1, c = 2, E = 1, nu = 0.3, interference
// delta = 1e-3), the inner one a <= r <= b + delta, the outer one b <= r <= c, length 0.5 with
// non-matching meshes along the axis (4 and 3 layers); their ends held axially (u_z = 0: the
// host leaves those dofs out of its equations) so that Lame's plane-strain solution is exact.
// The interference is an overlap of the two meshes in the reference coordinates the host gives
// (Host::add_pair's coordinates): one increment with no load closes it. The two surfaces
// overlap everywhere they are near each other, so the host says which side the outer tube is
// on (Host::set_pair_inside).
//
// Checked, with n elements through each wall (argument, default 8):
// - the interface pressure -tn at every node of the outer bore (A) against Lame's for the radii
//   modelled to 1e-9 (the axisymmetric hybrid element holds Lame's stress field exactly) and
//   the textbook p = E delta (b^2 - a^2)(c^2 - b^2) / (2 b^3 (1 - nu^2)(c^2 - a^2)) to 0.1%;
// - the full-circle measure: the A nodes' weights add up to the bore's area 2 pi b L, and
//   their radial contact forces to p 2 pi b L, both to 1e-9;
// - in the two elements beside the interface (one per tube): u_r of their interface node
//   against Lame's to 1e-9 (nodally exact) and sigma_theta at their centre
//   (hycon::element_stress) against Lame's there within 0.5 / n^2 (the stress is linear in an
//   element, its error falls as h^2: measured 2.7e-3 and 2.2e-4 at n = 8); their stress
//   parameters (hycon::element_stress_params: 7) and the traction on their interface edge
//   (hycon::element_edge_traction) against Lame's {-sigma_r, 0} within 2 / n in t_r (first
//   order: measured -15% and -2.2% at n = 8, where the multipliers are exact) and 1e-9 p in t_z;
// - the same mesh through the model API (hycon::Model: hycon assembles and factors): the
//   same contact states, tractions and displacements to 1e-9 of their largest values.
// Prints OK on success; FAILED or "wrong value" and exit code 1 otherwise.
#include "hycon.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

constexpr double kA = 0.5, kB = 1.0, kC = 2.0, kDelta = 1e-3, kLength = 0.5, kE = 1.0, kNu = 0.3;
constexpr std::size_t kLayersOuter = 4, kLayersInner = 3;
const double kPi = std::acos(-1.0);
const HyconMaterial kSteel{kE, kNu, 1.0, HYCON_AXISYMMETRIC};

// The meridian section: node coordinates (r z pairs), 4-node elements (counter-clockwise in
// (r, z)), the contact polylines and the nodes of the tubes' ends.
struct Mesh {
    std::size_t nr = 0;
    std::vector<double> coords;
    std::vector<std::size_t> offsets{0}, nodes, ends, a, b;
    std::size_t first_inner_element = 0;
    std::size_t n_nodes() const { return coords.size() / 2; }
};

// Append a tube r0 <= r <= r1, 0 <= z <= kLength of nr x nz elements; node (i, j) is
// first + j (nr + 1) + i. Returns `first`.
std::size_t tube(Mesh &m, double r0, double r1, std::size_t nz) {
    const std::size_t first = m.n_nodes(), nr = m.nr;
    for (std::size_t j = 0; j <= nz; ++j)
        for (std::size_t i = 0; i <= nr; ++i) {
            m.coords.push_back(r0 + (r1 - r0) * double(i) / double(nr));
            m.coords.push_back(kLength * double(j) / double(nz));
        }
    for (std::size_t j = 0; j < nz; ++j)
        for (std::size_t i = 0; i < nr; ++i) {
            const std::size_t n0 = first + j * (nr + 1) + i;
            m.nodes.insert(m.nodes.end(), {n0, n0 + 1, n0 + nr + 2, n0 + nr + 1});
            m.offsets.push_back(m.nodes.size());
        }
    for (std::size_t i = 0; i <= nr; ++i) {
        m.ends.push_back(first + i);
        m.ends.push_back(first + nz * (nr + 1) + i);
    }
    return first;
}

Mesh make_mesh(std::size_t nr) {
    Mesh m;
    m.nr = nr;
    tube(m, kB, kC, kLayersOuter);
    m.first_inner_element = m.offsets.size() - 1;
    const std::size_t inner = tube(m, kA, kB + kDelta, kLayersInner);
    // A: the outer bore (i = 0) from the top down; B: the inner tube's outside (i = nr) upward
    for (std::size_t j = 0; j <= kLayersOuter; ++j) m.a.push_back((kLayersOuter - j) * (nr + 1));
    for (std::size_t j = 0; j <= kLayersInner; ++j) m.b.push_back(inner + j * (nr + 1) + nr);
    return m;
}

// One element's 8 coordinates.
std::array<double, 8> element_coords(const Mesh &m, std::size_t e) {
    std::array<double, 8> xy{};
    for (std::size_t k = 0; k < 4; ++k) {
        xy[2 * k] = m.coords[2 * m.nodes[4 * e + k]];
        xy[2 * k + 1] = m.coords[2 * m.nodes[4 * e + k] + 1];
    }
    return xy;
}

// Lame's stresses (s_r, s_theta) at radius r of a tube r_in <= r <= r_out with pressure p_in
// inside and p_out outside, and u_r there in plane strain.
struct Lame {
    double sr, st, ur;
};
Lame lame(double r_in, double r_out, double p_in, double p_out, double r) {
    const double d = r_out * r_out - r_in * r_in;
    const double big_a = (p_in * r_in * r_in - p_out * r_out * r_out) / d;
    const double big_b = (p_in - p_out) * r_in * r_in * r_out * r_out / d;
    const double sr = big_a - big_b / (r * r), st = big_a + big_b / (r * r);
    return {sr, st, r * (1.0 + kNu) / kE * ((1.0 - kNu) * st - kNu * sr)};
}

// The interface pressure for the radii modelled: u_outer(b) - u_inner(b + delta) = delta with
// force balance p_outer b = p_inner (b + delta) (the same ring of the interface).
double lame_pressure() {
    const double d = kB + kDelta;
    const double u_outer = lame(kB, kC, 1.0, 0.0, kB).ur;
    const double u_inner = lame(kA, d, 0.0, 1.0, d).ur;
    return kDelta / (u_outer - u_inner * kB / d);
}

// The host's side: equation numbers (u_z of the ends held, left out), CSR stiffness.
struct HostSystem {
    std::vector<std::int64_t> eq;  // per dof, HYCON_FIXED if held
    std::size_t n_eq = 0;
    std::vector<std::size_t> row_ptr, columns;
    std::vector<double> values;
};

bool assemble(const Mesh &m, HostSystem &s) {
    s.eq.assign(2 * m.n_nodes(), 0);
    for (const std::size_t node : m.ends) s.eq[2 * node + 1] = HYCON_FIXED;
    for (std::int64_t &e : s.eq)
        if (e != HYCON_FIXED) e = std::int64_t(s.n_eq++);
    // lower triangle, row by row; a (row, column) met twice is summed by hycon
    std::vector<std::vector<std::pair<std::size_t, double>>> rows(s.n_eq);
    for (std::size_t e = 0; e + 1 < m.offsets.size(); ++e) {
        auto ke = hycon::element_stiffness(HYCON_ELEMENT_HYBRID, element_coords(m, e), kSteel);
        if (!ke) {
            std::printf("FAILED: element_stiffness of element %zu: %s\n", e,
                        ke.message().c_str());
            return false;
        }
        for (std::size_t i = 0; i < 8; ++i) {
            const std::int64_t ri = s.eq[2 * m.nodes[4 * e + i / 2] + i % 2];
            if (ri == HYCON_FIXED) continue;
            for (std::size_t j = 0; j < 8; ++j) {
                const std::int64_t cj = s.eq[2 * m.nodes[4 * e + j / 2] + j % 2];
                if (cj != HYCON_FIXED && cj <= ri)
                    rows[std::size_t(ri)].push_back({std::size_t(cj), (*ke)[i * 8 + j]});
            }
        }
    }
    s.row_ptr.push_back(0);
    for (const auto &row : rows) {
        for (const auto &[column, value] : row) {
            s.columns.push_back(column);
            s.values.push_back(value);
        }
        s.row_ptr.push_back(s.columns.size());
    }
    return true;
}

// What the two paths are compared on: the A nodes' results and every node's displacement.
struct Outcome {
    std::vector<HyconNodeResult> a;
    std::vector<double> u;  // 2 per node
};

int failures = 0;
void expect(bool ok, const char *what, double value) {
    if (!ok) {
        std::printf("wrong value: %s: %.10e\n", what, value);
        ++failures;
    }
}

#define TRY(result, what)                                                                      \
    if (!(result)) {                                                                           \
        std::printf("FAILED: %s: %s\n", what, (result).message().c_str());                    \
        return false;                                                                          \
    }

// Lame's solution in the outer tube (b <= r <= c, pressure p in its bore) or in the inner one
// (a <= r <= d = b + delta, pressure p b / d on its outside) at radius r.
Lame tube(bool outer, double p, double r) {
    const double d = kB + kDelta;
    return outer ? lame(kB, kC, p, 0.0, r) : lame(kA, d, 0.0, p * kB / d, r);
}

// The element of one tube beside the interface (its interface edge: 3 in the outer tube,
// 1 in the inner one) against Lame: u_r at its interface node, sigma_theta at its centre, its
// stress parameters and the traction on its interface edge.
bool check_beside_interface(const Mesh &m, const std::vector<double> &u, std::size_t e,
                            bool outer, double p) {
    const std::array<double, 8> xy = element_coords(m, e);
    std::array<double, 8> q{};
    for (std::size_t k = 0; k < 8; ++k) q[k] = u[2 * m.nodes[4 * e + k / 2] + k % 2];
    const std::size_t node = m.nodes[4 * e + (outer ? 0 : 1)];
    const double r = m.coords[2 * node], ur = tube(outer, p, r).ur;
    std::printf("  u_r at r = %.4f: %.10e, Lame %.10e (%+.1e)\n", r, u[2 * node], ur,
                u[2 * node] / ur - 1.0);
    expect(std::fabs(u[2 * node] / ur - 1.0) < 1e-9, "u_r / Lame - 1 on the interface",
           u[2 * node] / ur - 1.0);
    const double rc = 0.25 * (xy[0] + xy[2] + xy[4] + xy[6]);
    const double zc = 0.25 * (xy[1] + xy[3] + xy[5] + xy[7]);
    auto sigma = hycon::element_stress(HYCON_ELEMENT_HYBRID, xy, kSteel, q, rc, zc);
    TRY(sigma, "element_stress");
    const double hoop = tube(outer, p, rc).st, err = (*sigma)[3] / hoop - 1.0;
    std::printf("  sigma_theta at r = %.4f: %.10e, Lame %.10e (%+.1e)\n", rc, (*sigma)[3],
                hoop, err);
    // linear in the element: its error at the centre falls as h^2
    expect(std::fabs(err) < 0.5 / double(m.nr * m.nr), "sigma_theta / Lame - 1", err);
    auto beta = hycon::element_stress_params(HYCON_ELEMENT_HYBRID, xy, kSteel, q);
    TRY(beta, "element_stress_params");
    expect(beta->size() == 7, "stress parameters of the axisymmetric hybrid element",
           double(beta->size()));
    // Lame's {-sigma_r, 0} with the outward normal -r (outer) or +r (inner)
    auto t = hycon::element_edge_traction(HYCON_ELEMENT_HYBRID, xy, kSteel, q, outer ? 3 : 1, 0.5);
    TRY(t, "element_edge_traction");
    const double t_exact = outer ? p : -p * kB / (kB + kDelta);
    std::printf("  edge traction {t_r, t_z} = {%.10e, %.1e}, Lame {%.10e, 0} (%+.1e)\n",
                (*t)[0], (*t)[1], t_exact, (*t)[0] / t_exact - 1.0);
    // first order in h (the element's stress is linear, Lame's sigma_r is not)
    expect(std::fabs((*t)[0] / t_exact - 1.0) < 2.0 / double(m.nr), "edge t_r / Lame - 1",
           (*t)[0] / t_exact - 1.0);
    expect(std::fabs((*t)[1]) < 1e-9 * p, "edge t_z (in p)", (*t)[1] / p);
    return true;
}

// The pair in the host's numbering: node ids, reference coordinates (the overlap drawn in
// them) and equation numbers per polyline; A's side from a point inside the outer tube.
hycon::Result<std::size_t> describe_pair(hycon::Host &host, const Mesh &m, const HostSystem &s) {
    auto polyline = [&m, &s](const std::vector<std::size_t> &ids, std::vector<double> &xy,
                             std::vector<std::int64_t> &eqs) {
        for (const std::size_t node : ids)
            for (std::size_t d = 0; d < 2; ++d) {
                xy.push_back(m.coords[2 * node + d]);
                eqs.push_back(s.eq[2 * node + d]);
            }
    };
    std::vector<double> a_xy, b_xy;
    std::vector<std::int64_t> a_eq, b_eq;
    polyline(m.a, a_xy, a_eq);
    polyline(m.b, b_xy, b_eq);
    auto pair = host.add_pair(m.a, a_xy, a_eq, m.b, b_xy, b_eq, 0.0, HYCON_AXISYMMETRIC, 1.0);
    if (!pair) return pair;
    // the centroid of the outer tube's element at the top of the bore (A's first segment)
    const std::array<double, 8> xy = element_coords(m, (kLayersOuter - 1) * m.nr);
    const hycon::Status inside =
        host.set_pair_inside(*pair, {0.25 * (xy[0] + xy[2] + xy[4] + xy[6]),
                                     0.25 * (xy[1] + xy[3] + xy[5] + xy[7])});
    if (!inside) return inside;
    return pair;
}

// The host path: CSR assembled from hycon's element routines, hycon factors it.
bool run_host(const Mesh &m, const HostSystem &s, Outcome &out) {
    auto host = hycon::Host::create(s.n_eq);
    TRY(host, "Host::create");
    auto pair = describe_pair(*host, m, s);
    TRY(pair, "the pair (Host::add_pair, Host::set_pair_inside)");
    const hycon::Status csr = host->set_csr(s.row_ptr, s.columns, s.values, HYCON_CSR_LOWER);
    TRY(csr, "Host::set_csr");
    auto contact = hycon::Contact::create(*host);
    TRY(contact, "Contact::create (host)");
    const std::vector<double> load(s.n_eq, 0.0);  // no load: the overlap alone presses
    auto info = contact->increment(load);
    TRY(info, "increment (host)");
    auto a = contact->node_results(*pair);
    TRY(a, "node_results (host)");
    auto field = contact->displacement();  // over the host's equations
    TRY(field, "displacement (host)");
    auto forces = contact->forces();
    TRY(forces, "forces (host)");
    out.a = *a;
    out.u.assign(2 * m.n_nodes(), 0.0);
    for (std::size_t k = 0; k < out.u.size(); ++k)
        if (s.eq[k] != HYCON_FIXED) out.u[k] = (*field)[std::size_t(s.eq[k])];
    // the full circle: A's weights and radial contact forces over the bore's area 2 pi b L
    double fr = 0.0, weights = 0.0;
    for (const std::size_t node : m.a) fr += (*forces)[std::size_t(s.eq[2 * node])];
    for (const HyconNodeResult &r : out.a) weights += r.weight;
    const double p = lame_pressure(), area = 2.0 * kPi * kB * kLength;
    std::printf("host: %zu equations, %zu stored entries, %zu iterations, %zu active\n", s.n_eq,
                s.values.size(), info->iterations, info->active);
    std::printf("  sum of A weights %.10e = 2 pi b L %+.1e\n", weights, weights / area - 1.0);
    std::printf("  radial contact force on A %.10e = p 2 pi b L %+.1e\n", fr,
                fr / (p * area) - 1.0);
    expect(std::fabs(weights / area - 1.0) < 1e-9, "sum of A weights / 2 pi b L", weights);
    expect(std::fabs(fr / (p * area) - 1.0) < 1e-9, "radial force on A / p 2 pi b L", fr);
    return check_beside_interface(m, out.u, (kLayersOuter - 1) * m.nr, true, p) &&
           check_beside_interface(m, out.u, m.first_inner_element + m.nr - 1, false, p);
}

// The model API on the same mesh: hycon assembles and factors.
bool run_model(const Mesh &m, Outcome &out) {
    auto model = hycon::Model::create(m.coords, m.offsets, m.nodes,
                                      std::array<HyconMaterial, 1>{kSteel}, HYCON_ELEMENT_HYBRID);
    TRY(model, "Model::create");
    const hycon::Status held = model->prescribe(m.ends, HYCON_Y);
    TRY(held, "Model::prescribe");
    auto pair = model->add_pair(m.a, m.b, 0.0);
    TRY(pair, "Model::add_pair");
    auto contact = hycon::Contact::create(*model);
    TRY(contact, "Contact::create (model)");
    const std::vector<double> zero(2 * m.n_nodes(), 0.0);
    auto info = contact->increment(zero, zero);
    TRY(info, "increment (model)");
    auto a = contact->node_results(*pair);
    TRY(a, "node_results (model)");
    auto u = contact->displacement();
    TRY(u, "displacement (model)");
    out.a = *a;
    out.u = *u;
    return true;
}

double max_abs(const std::vector<double> &v) {
    double m = 0.0;
    for (const double x : v) m = std::max(m, std::fabs(x));
    return m;
}

}  // namespace

int main(int argc, char **argv) {
    const std::size_t nr = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 8;
    if (nr < 1 || nr > 256) {
        std::printf("FAILED: elements through each wall must be 1 to 256\n");
        return EXIT_FAILURE;
    }
    const Mesh mesh = make_mesh(nr);
    HostSystem system;
    Outcome host, model;
    if (!assemble(mesh, system) || !run_host(mesh, system, host) || !run_model(mesh, model))
        return EXIT_FAILURE;
    const double p = lame_pressure();
    const double p_book = kE * kDelta * (kB * kB - kA * kA) * (kC * kC - kB * kB) /
                          (2.0 * kB * kB * kB * (1.0 - kNu * kNu) * (kC * kC - kA * kA));
    std::printf("shrink fit, %zu elements through each wall\n", nr);
    std::printf("Lame (radii modelled) p = %.10e, textbook p = %.10e\n", p, p_book);
    double dt = 0.0;
    bool same_states = host.a.size() == model.a.size();
    for (std::size_t k = 0; k < host.a.size() && same_states; ++k) {
        const double pk = -host.a[k].tn;
        std::printf("  z = %.4f  p = %.10e  (%+.1e vs Lame, %+.1e vs textbook)\n",
                    host.a[k].position[1], pk, pk / p - 1.0, pk / p_book - 1.0);
        expect(std::fabs(pk / p - 1.0) < 1e-9, "host pressure / Lame - 1", pk / p - 1.0);
        expect(std::fabs(pk / p_book - 1.0) < 1e-3, "host pressure / textbook - 1",
               pk / p_book - 1.0);
        same_states = same_states && host.a[k].state == model.a[k].state;
        dt = std::max({dt, std::fabs(host.a[k].tn - model.a[k].tn),
                       std::fabs(host.a[k].ts - model.a[k].ts)});
    }
    double du = 0.0;
    for (std::size_t k = 0; k < host.u.size(); ++k)
        du = std::max(du, std::fabs(host.u[k] - model.u[k]));
    const double rel_t = dt / p, rel_u = du / max_abs(model.u);
    std::printf("host against model API: tractions %.1e of p, displacements %.1e of the "
                "largest\n", rel_t, rel_u);
    expect(same_states, "contact states of host and model API differ", 0.0);
    expect(rel_t < 1e-9, "host - model tractions (in p)", rel_t);
    expect(rel_u < 1e-9, "host - model displacements (relative)", rel_u);
    if (failures != 0) {
        std::printf("FAILED: %d checks\n", failures);
        return EXIT_FAILURE;
    }
    std::printf("OK\n");
    return EXIT_SUCCESS;
}
