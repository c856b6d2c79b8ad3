// A block pressed on a flat and dragged over it with friction, in 3D from C++17 through
// include/hycon.hpp (hycon::SolidModel, hycon::SolidContact; issue #43).
//
// Set-up (E = 1, nu = 0.3 for both bodies, 18-beta hybrid bricks, mu = 0.3): the flat B is the
// box [0, L]^2 x [-H, 0], the block A the box [0, L]^2 x [0, H] on it (L = 2, H = 1), each of
// n x n x n/2 bricks (n the argument). The flat's bottom is held in z, its face x = 0 in x; the
// nodes of both bodies on y = 0 are held in y (a declared symmetry plane). The block's top is
// prescribed in x, y and z: moved down by delta = 1e-3 with the sideways expansion of the
// uniform state below (x, y times nu delta / 2H), then also along x by s (the drag) in steps
// up to 2 delta. A = the block's bottom faces, B = the flat's top faces.
//
// Checked (a failure prints FAILED and the program exits nonzero):
// * pressed: the two bodies of one material in uniaxial stress sigma = -E delta / (2 H) expand
//   alike sideways, so nothing slips: every A node sticks with tn = sigma to 1e-8 and ts = 0 to
//   1e-8 |sigma|, the normal force P = -sigma L^2 to 1e-8 (the hybrid bricks and the contact
//   elements reproduce a uniform stress exactly);
// * at every step: tn <= 0, stick nodes inside the cone |ts| <= mu |tn| (1 + 1e-6), slip nodes
//   on it |ts| = mu |tn| to 1e-9 with the friction traction opposing the slip direction, and
//   B's contact forces balance A's to 1e-10 P;
// * dragged: the traction on A opposes the drag (Q = -sum f_x > 0) and grows with s; at s =
//   2 delta every A node slips (gross sliding) and Q / P = mu to 0.5% (the slip directions
//   tilt off x where the block's sideways Poisson expansion varies).
// Measured (release library): pressed |tn / sigma - 1| <= 2.2e-14 at n = 8; at s = 2 delta
// Q / P = 0.299811, 0.299837, 0.299908 at n = 8, 4, 2 (-0.06% to -0.03% of mu).
//
// Usage: solid_block_cpp [n] (bricks a side, even, 2..16, default 8; 4 for the valgrind and
// ASan runs).
#include "hycon.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr double kE = 1.0, kNu = 0.3, kMu = 0.3;
constexpr double kL = 2.0, kH = 1.0, kDelta = 1e-3;
constexpr double kUniform = 1e-8;   // the pressed state's uniform stress, relative
constexpr double kSlipLaw = 1e-9;   // |ts| = mu |tn| at slip nodes, relative
constexpr double kCone = 1e-6;      // |ts| <= mu |tn| (1 + kCone) at stick nodes
constexpr double kBalance = 1e-10;  // B's forces against A's, relative to P
constexpr double kSliding = 0.005;  // Q / P against mu in gross sliding, relative

int failures = 0;

void expect(bool ok, const std::string &what) {
    if (!ok) {
        std::fprintf(stderr, "FAILED: %s\n", what.c_str());
        ++failures;
    }
}

[[noreturn]] void die(const char *what, const hycon::Status &status) {
    std::fprintf(stderr, "FAILED: %s: %s (%d): %s\n", what, status.name(), int(status.code()),
                 status.message().c_str());
    std::exit(EXIT_FAILURE);
}

template <class T>
T take(hycon::Result<T> result, const char *what) {
    if (!result) die(what, result.status());
    return std::move(result).value();
}

void require(const hycon::Status &status, const char *what) {
    if (!status) die(what, status);
}

// The two boxes: node (i, j, k) of a body is first + i + (n + 1) (j + (n + 1) k); the flat's
// nodes first, its bottom layer first.
struct Mesh {
    std::size_t n, nz, per_body;
    std::vector<double> coords;
    std::vector<std::size_t> bricks;
    std::vector<hycon::BrickFace> a, b;

    std::size_t node(std::size_t body, std::size_t i, std::size_t j, std::size_t k) const {
        return body * per_body + i + (n + 1) * (j + (n + 1) * k);
    }
    const double *x(std::size_t id) const { return &coords[3 * id]; }
};

Mesh build(std::size_t n) {
    Mesh m{n, n / 2, (n + 1) * (n + 1) * (n / 2 + 1), {}, {}, {}, {}};
    for (std::size_t body = 0; body < 2; ++body) {
        const double z0 = body == 0 ? -kH : 0.0;
        for (std::size_t k = 0; k <= m.nz; ++k)
            for (std::size_t j = 0; j <= n; ++j)
                for (std::size_t i = 0; i <= n; ++i) {
                    m.coords.push_back(kL * double(i) / double(n));
                    m.coords.push_back(kL * double(j) / double(n));
                    m.coords.push_back(z0 + kH * double(k) / double(m.nz));
                }
    }
    for (std::size_t body = 0; body < 2; ++body)
        for (std::size_t k = 0; k < m.nz; ++k)
            for (std::size_t j = 0; j < n; ++j)
                for (std::size_t i = 0; i < n; ++i) {
                    const std::size_t brick = m.bricks.size() / 8;
                    const std::array<std::size_t, 8> ids = {
                        m.node(body, i, j, k),         m.node(body, i + 1, j, k),
                        m.node(body, i + 1, j + 1, k), m.node(body, i, j + 1, k),
                        m.node(body, i, j, k + 1),     m.node(body, i + 1, j, k + 1),
                        m.node(body, i + 1, j + 1, k + 1), m.node(body, i, j + 1, k + 1)};
                    m.bricks.insert(m.bricks.end(), ids.begin(), ids.end());
                    // A: the block's bottom layer, local face 4; B: the flat's top, face 5
                    if (body == 1 && k == 0) m.a.push_back({brick, 4});
                    if (body == 0 && k + 1 == m.nz) m.b.push_back({brick, 5});
                }
    return m;
}

// The nodes of `body` (or both, body = 2) where coordinate `d` is `value`.
std::vector<std::size_t> on_plane(const Mesh &m, std::size_t body, std::size_t d, double value) {
    std::vector<std::size_t> ids;
    for (std::size_t id = 0; id < 2 * m.per_body; ++id)
        if ((body == 2 || id / m.per_body == body) && m.x(id)[d] == value) ids.push_back(id);
    return ids;
}

// The flat's bottom in z, its face x = 0 in x, both bodies' faces y = 0 in y (the block's
// below its top), the block's top in x, y and z.
std::vector<std::size_t> hold(hycon::SolidModel &model, const Mesh &m) {
    std::vector<std::size_t> block_y0;
    for (std::size_t id : on_plane(m, 1, 1, 0.0))
        if (m.x(id)[2] != kH) block_y0.push_back(id);
    const std::vector<std::size_t> top = on_plane(m, 1, 2, kH);
    require(model.prescribe(on_plane(m, 0, 2, -kH), HYCON_Z), "prescribe the flat's bottom");
    require(model.prescribe(on_plane(m, 0, 0, 0.0), HYCON_X), "prescribe the flat's x = 0");
    require(model.prescribe(on_plane(m, 0, 1, 0.0), HYCON_Y), "prescribe the flat's y = 0");
    require(model.prescribe(block_y0, HYCON_Y), "prescribe the block's y = 0");
    require(model.prescribe(top, HYCON_XYZ), "prescribe the block's top");
    require(model.add_symmetry_plane({0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}), "symmetry plane y = 0");
    return top;
}

// The block's top: the uniform state's sideways expansion (strain nu delta / 2H), moved down
// by delta and along x by the drag s.
void top_values(const Mesh &m, const std::vector<std::size_t> &top, double s,
                std::vector<double> &prescribed) {
    const double lateral = kNu * kDelta / (2.0 * kH);
    for (std::size_t id : top) {
        prescribed[3 * id] = lateral * m.x(id)[0] + s;
        prescribed[3 * id + 1] = lateral * m.x(id)[1];
        prescribed[3 * id + 2] = -kDelta;
    }
}

// What one converged increment looks like.
struct Summary {
    std::size_t stick = 0, slip = 0, open = 0;
    double p = 0.0, q = 0.0;  // P = sum f_z, Q = -sum f_x over A's nodal forces
    double tn_error = 0.0, ts_max = 0.0, tilt = 0.0;
};

Summary check_step(const hycon::SolidContact &contact, double sigma, const std::string &step) {
    const auto a = take(contact.node_results(0), "node results");
    const auto b = take(contact.b_node_results(0), "B node results");
    Summary s;
    std::array<double, 3> on_a{}, on_b{};
    for (const HyconSolidNodeResult &r : a) {
        const double ts = std::hypot(r.ts[0], r.ts[1]), cone = kMu * std::fabs(r.tn);
        const std::string at = step + ", A node " + std::to_string(r.node);
        s.stick += r.state == HYCON_NODE_STICK;
        s.slip += r.state == HYCON_NODE_SLIP;
        s.open += r.state == HYCON_NODE_OPEN;
        s.tn_error = std::fmax(s.tn_error, std::fabs(r.tn / sigma - 1.0));
        s.ts_max = std::fmax(s.ts_max, ts / std::fabs(sigma));
        expect(r.tn <= 0.0, at + ": no tension");
        if (r.state == HYCON_NODE_STICK)
            expect(ts <= cone * (1.0 + kCone), at + ": a stick node inside the cone");
        if (r.state == HYCON_NODE_SLIP) {
            const double along = r.ts[0] * r.slip_direction[0] + r.ts[1] * r.slip_direction[1];
            expect(std::fabs(ts - cone) <= kSlipLaw * cone, at + ": |ts| = mu |tn| at a slip node");
            expect(std::fabs(along + ts) <= kSlipLaw * cone, at + ": friction opposes the slip");
            // the slip direction in x y z: off the drag's x by the sideways expansion
            const double sx = r.slip_direction[0] * r.tangent[0][0] +
                              r.slip_direction[1] * r.tangent[1][0];
            s.tilt = std::fmax(s.tilt, 1.0 - std::fabs(sx));
        }
        for (std::size_t d = 0; d < 3; ++d) on_a[d] += r.force[d];
    }
    for (const HyconSolidBNodeResult &r : b)
        for (std::size_t d = 0; d < 3; ++d) on_b[d] += r.force[d];
    s.p = on_a[2];
    s.q = -on_a[0];
    for (std::size_t d = 0; d < 3; ++d)
        expect(std::fabs(on_a[d] + on_b[d]) <= kBalance * s.p, step + ": B's forces balance A's");
    return s;
}

}  // namespace

int main(int argc, char **argv) {
    const long arg = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 8;
    if (arg < 2 || arg > 16 || arg % 2 != 0) {
        std::fprintf(stderr, "FAILED: n must be even, in 2..16\n");
        return EXIT_FAILURE;
    }
    const Mesh m = build(std::size_t(arg));
    const HyconSolidMaterial material = {kE, kNu};
    auto model = take(hycon::SolidModel::create(m.coords, m.bricks,
                                                hycon::View<HyconSolidMaterial>(&material, 1),
                                                HYCON_BRICK_HYBRID18),
                      "SolidModel::create");
    const std::vector<std::size_t> top = hold(model, m);
    take(model.add_pair(m.a, m.b, kMu), "add_pair");
    auto contact = take(hycon::SolidContact::create(model), "SolidContact::create");
    const std::size_t n_dofs = take(contact.field_len(), "field_len");
    const std::vector<double> load(n_dofs, 0.0);
    std::vector<double> prescribed(n_dofs, 0.0);
    top_values(m, top, 0.0, prescribed);

    const double sigma = -kE * kDelta / (2.0 * kH);
    std::printf("block on a flat, %zu x %zu x %zu bricks each, mu = %g: sigma = %.6e\n", m.n, m.n,
                m.nz, kMu, sigma);
    const auto pressed_info = take(contact.increment(load, prescribed), "press");
    const Summary pressed = check_step(contact, sigma, "pressed");
    std::printf("pressed: %zu iterations, %zu stick, %zu slip, %zu open; |tn/sigma - 1| <= "
                "%.1e, |ts|/|sigma| <= %.1e, P / (-sigma L^2) - 1 = %+.1e\n",
                pressed_info.iterations, pressed.stick, pressed.slip, pressed.open,
                pressed.tn_error, pressed.ts_max, pressed.p / (-sigma * kL * kL) - 1.0);
    expect(pressed.stick == (m.n + 1) * (m.n + 1), "pressed: every A node sticks");
    expect(pressed.tn_error <= kUniform, "pressed: tn = sigma at every A node");
    expect(pressed.ts_max <= kUniform, "pressed: ts = 0 at every A node");
    expect(std::fabs(pressed.p / (-sigma * kL * kL) - 1.0) <= kUniform, "pressed: P = -sigma L^2");

    double last_q = 0.0;
    Summary dragged;
    for (const double fraction : {0.05, 0.2, 0.5, 1.0, 2.0}) {
        const double s = fraction * kDelta;
        top_values(m, top, s, prescribed);
        const auto info = take(contact.increment(load, prescribed), "drag");
        char step[64];
        std::snprintf(step, sizeof step, "dragged by %g delta", fraction);
        dragged = check_step(contact, sigma, step);
        std::printf("%s: %zu iterations, %zu stick, %zu slip, %zu open; Q/P = %.6f, slip "
                    "directions off x by <= %.1e\n",
                    step, info.iterations, dragged.stick, dragged.slip, dragged.open,
                    dragged.q / dragged.p, dragged.tilt);
        expect(dragged.q > last_q, std::string(step) + ": Q > 0 and growing with s");
        last_q = dragged.q;
    }
    expect(dragged.slip == (m.n + 1) * (m.n + 1), "at 2 delta every A node slips");
    expect(std::fabs(dragged.q / dragged.p / kMu - 1.0) <= kSliding, "gross sliding: Q/P = mu");
    if (failures > 0) {
        std::fprintf(stderr, "%d check(s) FAILED\n", failures);
        return EXIT_FAILURE;
    }
    std::printf("ok\n");
    return 0;
}
