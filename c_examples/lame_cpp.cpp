// Lame's thick cylinder solved by a tiny axisymmetric host code in C++17 that takes only the
// element stiffness matrices (hycon_element_stiffness with a HYCON_AXISYMMETRIC material) and
// the element stresses (hycon::element_stress from hycon.hpp) from hycon.
//
// MacNeal and Harder's data: inner radius a = 3, outer b = 9, E = 1000, internal pressure p = 1,
// plane strain (u_z = 0 at every node: both ends held). The meridian section r in [a, b] is
// meshed with n equal elements through the wall and one layer along the axis. Axisymmetric
// element matrices are for the full circle (measure 2 pi r), so the pressure's nodal forces are
// p 2 pi a h / 2 at the two bore nodes. Only the radial dofs are free; a dense Cholesky solves.
//
// Checks, for nu = 0.3, 0.49, 0.4999: the hybrid element's u_r(a) within 0.5% of Lame's
// u_r = r (1 + nu) / E ((1 - nu) sigma_theta - nu sigma_r) at n (default 20) and on
// MacNeal-Harder's 5 elements; Q4's at nu = 0.4999 more than half off (it locks) when n <= 20;
// the hybrid element's 4 stress components at the first element's centre (sigma_theta and
// sigma_z within 1 / n^2 of Lame's there: 0.25% at n = 20, 4% at n = 5; measured 0.20% and
// 2.5%). Usage: lame_cpp [n]. Prints OK on success.
#include "hycon.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

constexpr double kA = 3.0, kB = 9.0, kE = 1000.0, kP = 1.0;
const double kPi = std::acos(-1.0);

// Lame's radial and hoop stress and radial displacement at radius r.
struct Lame {
    double sr, st, ur;
};
Lame lame(double r, double nu) {
    const double big_b = kP * kA * kA * kB * kB / (kB * kB - kA * kA), big_a = big_b / (kB * kB);
    const double sr = big_a - big_b / (r * r), st = big_a + big_b / (r * r);
    return {sr, st, r * (1.0 + nu) / kE * ((1.0 - nu) * st - nu * sr)};
}

// Dense symmetric positive definite solve (Cholesky, in place); false if not positive definite.
bool spd_solve(std::vector<double> &k, std::vector<double> &f) {
    const std::size_t m = f.size();
    auto at = [&k, m](std::size_t i, std::size_t j) -> double & { return k[i * m + j]; };
    for (std::size_t j = 0; j < m; ++j) {
        double d = at(j, j);
        for (std::size_t s = 0; s < j; ++s) d -= at(j, s) * at(j, s);
        if (!(d > 0.0)) return false;
        at(j, j) = std::sqrt(d);
        for (std::size_t i = j + 1; i < m; ++i) {
            double v = at(i, j);
            for (std::size_t s = 0; s < j; ++s) v -= at(i, s) * at(j, s);
            at(i, j) = v / at(j, j);
        }
    }
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t s = 0; s < i; ++s) f[i] -= at(i, s) * f[s];
        f[i] /= at(i, i);
    }
    for (std::size_t i = m; i-- > 0;) {
        for (std::size_t s = i + 1; s < m; ++s) f[i] -= at(s, i) * f[s];
        f[i] /= at(i, i);
    }
    return true;
}

struct Outcome {
    bool ok = false;
    double bore = 0.0;                     // u_r(a) / Lame
    std::vector<double> stress;            // 4 components at the first element's centre
    double centre_r = 0.0;                 // radius of that centre
};

// Node 2 i is (r_i, 0), node 2 i + 1 is (r_i, h); the radial dof of node k is equation k.
Outcome solve(HyconElementKind kind, double nu, std::size_t n) {
    const HyconMaterial material{kE, nu, 1.0, HYCON_AXISYMMETRIC};
    const double h = (kB - kA) / double(n);
    const std::size_t m = 2 * (n + 1);
    auto radius = [n](std::size_t i) { return kA + (kB - kA) * double(i) / double(n); };
    std::vector<double> k(m * m, 0.0), f(m, 0.0);
    auto element = [&](std::size_t i, std::array<std::size_t, 4> &ids) {
        ids = {2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1};  // counter-clockwise in (r, z)
        return std::array<double, 8>{radius(i), 0.0, radius(i + 1), 0.0,
                                     radius(i + 1), h, radius(i), h};
    };
    Outcome out;
    for (std::size_t i = 0; i < n; ++i) {
        std::array<std::size_t, 4> ids{};
        const std::array<double, 8> coords = element(i, ids);
        std::array<double, 64> ke{};
        const HyconStatus s = hycon_element_stiffness(kind, 4, coords.data(), &material,
                                                      ke.data(), ke.size());
        if (s != HYCON_OK) {
            std::printf("FAILED: hycon_element_stiffness: %s\n",
                        hycon::last_error_message().c_str());
            return out;
        }
        for (std::size_t a = 0; a < 4; ++a)  // radial rows and columns only (u_z = 0)
            for (std::size_t b = 0; b < 4; ++b) k[ids[a] * m + ids[b]] += ke[(2 * a) * 8 + 2 * b];
    }
    const double bore_force = kP * 2.0 * kPi * kA * h / 2.0;  // full circle
    f[0] += bore_force;
    f[1] += bore_force;
    if (!spd_solve(k, f)) {
        std::printf("FAILED: the assembled stiffness is not positive definite\n");
        return out;
    }
    out.bore = f[0] / lame(kA, nu).ur;
    std::array<std::size_t, 4> ids{};
    const std::array<double, 8> coords = element(0, ids);
    std::array<double, 8> q{};
    for (std::size_t a = 0; a < 4; ++a) q[2 * a] = f[ids[a]];
    out.centre_r = 0.5 * (radius(0) + radius(1));
    auto stress = hycon::element_stress(kind, coords, material, q, out.centre_r, 0.5 * h);
    if (!stress) {
        std::printf("FAILED: element_stress: %s\n", stress.message().c_str());
        return out;
    }
    out.stress = *std::move(stress);
    out.ok = true;
    return out;
}

}  // namespace

int main(int argc, char **argv) {
    const std::size_t n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 20;
    if (n < 1) return EXIT_FAILURE;
    int failures = 0;
    auto expect = [&failures](bool ok, const char *what, double nu, double got) {
        if (!ok) {
            std::printf("FAILED: %s at nu = %g: %.6f\n", what, nu, got);
            ++failures;
        }
    };
    std::printf("u_r(a) / Lame   %zu elements: hybrid  Q4      5 elements: hybrid  Q4\n", n);
    for (const double nu : {0.3, 0.49, 0.4999}) {
        const Outcome hybrid = solve(HYCON_ELEMENT_HYBRID, nu, n);
        const Outcome q4 = solve(HYCON_ELEMENT_Q4, nu, n);
        const Outcome hybrid5 = solve(HYCON_ELEMENT_HYBRID, nu, 5);
        const Outcome q45 = solve(HYCON_ELEMENT_Q4, nu, 5);
        if (!(hybrid.ok && q4.ok && hybrid5.ok && q45.ok)) return EXIT_FAILURE;
        std::printf("nu = %-6g                  %.5f %.5f             %.5f %.5f\n", nu,
                    hybrid.bore, q4.bore, hybrid5.bore, q45.bore);
        expect(std::fabs(hybrid.bore - 1.0) < 5e-3, "hybrid u_r(a) off by more than 0.5%", nu,
               hybrid.bore);
        expect(std::fabs(hybrid5.bore - 1.0) < 5e-3, "hybrid u_r(a), 5 elements", nu,
               hybrid5.bore);
        if (nu == 0.4999 && n <= 20)
            expect(q4.bore < 0.5, "Q4 should lock at nu = 0.4999", nu, q4.bore);
        const Lame exact = lame(hybrid.centre_r, nu);
        expect(hybrid.stress.size() == 4, "4 stress components in axisymmetry", nu,
               double(hybrid.stress.size()));
        if (hybrid.stress.size() == 4) {
            const double hoop = hybrid.stress[3] / exact.st;
            std::printf("             sigma_theta / Lame at the first element's centre: %.5f\n",
                        hoop);
            // the stress is linear in an element: its error at the centre falls as h^2
            const double tol = 1.0 / double(n * n);
            expect(std::fabs(hoop - 1.0) < tol, "hybrid sigma_theta / Lame", nu, hoop);
            expect(std::fabs(hybrid.stress[1] - nu * (exact.sr + exact.st)) <
                       tol * std::fabs(exact.st),
                   "hybrid sigma_z = nu (sigma_r + sigma_theta)", nu, hybrid.stress[1]);
        }
    }
    if (failures != 0) return EXIT_FAILURE;
    std::printf("OK\n");
    return EXIT_SUCCESS;
}
