// MacNeal and Harder's straight cantilever (regular mesh, in-plane shear) solved by a tiny C++17
// host through hycon.hpp's brick wrappers: 6 x 1 x 1 bricks over [0, 6] x [0, 0.2] x [0, 0.1],
// E = 1e7, nu = 0.3, clamped at x = 0, a unit tip force along y spread over the 4 tip nodes. The
// host assembles a dense matrix of the free dofs and factors it with its own Cholesky. The mean
// tip deflection, normalised by the reference 0.1081, must be 0.981 for the hybrid brick (the
// value tests/solid_validation.rs checks) and below 0.1 for the locking H8.
//
// Then the shape policy through the wrapper, on the front brick of MacNeal and Harder's 3D patch
// test (det J < 0 at its corner node 7, a face warped by 48 degrees; brick_patch.c solves the
// whole patch): hycon::brick_shape is an error under HYCON_SHAPE_STRICT and ok() with
// HYCON_WARNING_SHAPE and the report under the default policy, and hycon::brick_stiffness
// returns the matrix with the warning.
//
// Usage: brick_macneal_cpp. Prints OK on success.
#include "hycon.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr std::size_t kBricks = 6;
constexpr std::size_t kNodes = 4 * (kBricks + 1);

std::array<double, 3> node_xyz(std::size_t id) {
    const std::size_t row = kBricks + 1;
    const std::size_t i = id % row, j = (id / row) % 2, k = id / (2 * row);
    return {static_cast<double>(i), 0.2 * static_cast<double>(j), 0.1 * static_cast<double>(k)};
}

std::array<std::size_t, 8> brick_nodes(std::size_t e) {
    const std::size_t row = kBricks + 1, layer = 2 * row;
    const std::array<std::size_t, 4> bottom{e, e + 1, e + 1 + row, e + row};
    return {bottom[0], bottom[1], bottom[2], bottom[3],
            bottom[0] + layer, bottom[1] + layer, bottom[2] + layer, bottom[3] + layer};
}

// Mean tip deflection along y, or a negative value after printing the failure.
double solve(HyconBrickKind kind) {
    const HyconSolidMaterial material{1e7, 0.3};
    std::vector<long> eq(3 * kNodes);
    std::size_t n = 0;
    for (std::size_t d = 0; d < eq.size(); ++d)
        eq[d] = node_xyz(d / 3)[0] == 0.0 ? -1 : static_cast<long>(n++);
    std::vector<double> a(n * n, 0.0), f(n, 0.0);
    for (std::size_t e = 0; e < kBricks; ++e) {
        const auto nodes = brick_nodes(e);
        std::array<double, 24> x{};
        for (std::size_t c = 0; c < 8; ++c)
            for (std::size_t i = 0; i < 3; ++i) x[3 * c + i] = node_xyz(nodes[c])[i];
        const auto k = hycon::brick_stiffness(kind, x, material);
        if (!k) {
            std::printf("wrong value: brick_stiffness failed: %s\n", k.message().c_str());
            return -1.0;
        }
        for (std::size_t p = 0; p < 24; ++p)
            for (std::size_t q = 0; q < 24; ++q) {
                const long r = eq[3 * nodes[p / 3] + p % 3], c = eq[3 * nodes[q / 3] + q % 3];
                if (r < 0 || c < 0) continue;
                const auto ru = static_cast<std::size_t>(r), cu = static_cast<std::size_t>(c);
                a[ru * n + cu] += (*k)[p * 24 + q];
            }
    }
    for (std::size_t id = 0; id < kNodes; ++id)
        if (node_xyz(id)[0] == 6.0) f[static_cast<std::size_t>(eq[3 * id + 1])] += 0.25;
    // dense Cholesky a = L L^T in place (lower triangle), then the two triangular solves
    for (std::size_t j = 0; j < n; ++j) {
        double d = a[j * n + j];
        for (std::size_t k = 0; k < j; ++k) d -= a[j * n + k] * a[j * n + k];
        if (d <= 0.0) {
            std::printf("wrong value: matrix not positive definite\n");
            return -1.0;
        }
        a[j * n + j] = std::sqrt(d);
        for (std::size_t i = j + 1; i < n; ++i) {
            double s = a[i * n + j];
            for (std::size_t k = 0; k < j; ++k) s -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = s / a[j * n + j];
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t k = 0; k < i; ++k) f[i] -= a[i * n + k] * f[k];
        f[i] /= a[i * n + i];
    }
    for (std::size_t i = n; i-- > 0;) {
        for (std::size_t k = i + 1; k < n; ++k) f[i] -= a[k * n + i] * f[k];
        f[i] /= a[i * n + i];
    }
    double v = 0.0;
    for (std::size_t id = 0; id < kNodes; ++id)
        if (node_xyz(id)[0] == 6.0) v += 0.25 * f[static_cast<std::size_t>(eq[3 * id + 1])];
    return v;
}

// The shape policy on MacNeal-Harder's front brick: true when every check holds.
bool shape_policy() {
    const std::array<double, 24> front{0.0,   0.0,   0.0,   1.0,   0.0,   0.0,   0.826, 0.288,
                                       0.288, 0.249, 0.342, 0.192, 0.0,   0.0,   1.0,   1.0,
                                       0.0,   1.0,   0.677, 0.305, 0.683, 0.320, 0.186, 0.643};
    const auto strict = hycon::brick_shape(HYCON_BRICK_HYBRID18, front, HYCON_SHAPE_STRICT);
    const auto relaxed =
        hycon::brick_shape(HYCON_BRICK_HYBRID18, front, HYCON_SHAPE_INTEGRATION_POINTS);
    const auto k = hycon::brick_stiffness(HYCON_BRICK_HYBRID18, front, HyconSolidMaterial{1e6, 0.25});
    std::printf("front brick: strict %s, default %s: %s\n", strict.status().name(),
                relaxed.status().name(), relaxed.message().c_str());
    return strict.code() == HYCON_ERROR_BAD_ELEMENT &&
           strict.message().find("local node 7") != std::string::npos &&
           relaxed.code() == HYCON_WARNING_SHAPE && relaxed->corner == 7 &&
           relaxed->warnings == (HYCON_SHAPE_CORNER_JACOBIAN | HYCON_SHAPE_WARPED_FACE) &&
           relaxed->integration_jacobian > 6e-3 && std::fabs(relaxed->warp_degrees - 48.0) < 0.05 &&
           k.ok() && k.code() == HYCON_WARNING_SHAPE && (*k)[0] > 0.0;
}

}  // namespace

int main() {
    const double hybrid = solve(HYCON_BRICK_HYBRID18) / 0.1081;
    const double h8 = solve(HYCON_BRICK_H8) / 0.1081;
    std::printf("MacNeal-Harder regular cantilever, in-plane shear: hybrid18 %.3f, h8 %.3f\n",
                hybrid, h8);
    if (std::fabs(hybrid - 0.981) > 0.002 || h8 < 0.0 || h8 > 0.1 || !shape_policy()) {
        std::printf("wrong value\n");
        return EXIT_FAILURE;
    }
    std::printf("OK\n");
    return EXIT_SUCCESS;
}
