// Cook's membrane solved by a tiny host finite-element code in C++17 that takes only the
// element stiffness matrices from hycon (the C++ twin of cook_c.c).
//
// Geometry: the bilinear map of the unit square onto the quadrilateral (0,0), (48,44), (48,60),
// (0,44), meshed n x n. E = 1, nu = 1/3, t = 1, plane stress; clamped at x = 0; total vertical
// shear 1 uniformly distributed on x = 48 (consistent nodal forces). Dense Cholesky of the free
// dofs; v(48, 52) is checked against the published values.
//
// Usage: cook_cpp [max_n]   (meshes 2, 4, 8, 16 up to max_n; default 16). Prints OK on success.
#include "hycon.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

namespace {

// Print the failing call with hycon's last error message and stop (no exceptions needed).
void report_failure(const char *call, HyconStatus status, const char *file, int line) {
    std::string message(hycon_last_error_message(nullptr, 0), '\0');
    hycon_last_error_message(message.data(), message.size());
    message.pop_back();  // the NUL
    std::fprintf(stderr, "%s:%d: %s returned %s (%d): %s\n", file, line, call,
                 hycon_status_name(status), int(status), message.c_str());
    std::exit(EXIT_FAILURE);
}

#define CHECK(call)                                                                            \
    do {                                                                                       \
        HyconStatus check_status_ = (call);                                                    \
        if (check_status_ != HYCON_OK) report_failure(#call, check_status_, __FILE__, __LINE__); \
    } while (0)

struct Point {
    double x, y;
};

class CookMesh {
  public:
    explicit CookMesh(std::size_t n) : n_(n) {}
    std::size_t n() const { return n_; }
    std::size_t nodes() const { return (n_ + 1) * (n_ + 1); }
    std::size_t id(std::size_t i, std::size_t j) const { return j * (n_ + 1) + i; }
    Point at(std::size_t i, std::size_t j) const {
        const double xi = double(i) / double(n_), eta = double(j) / double(n_);
        return {48.0 * xi, 44.0 * xi * (1.0 - eta) + 60.0 * xi * eta + 44.0 * (1.0 - xi) * eta};
    }

  private:
    std::size_t n_;
};

// Dense symmetric positive definite system of the free dofs, factored in place.
class DenseSpd {
  public:
    explicit DenseSpd(std::size_t m) : m_(m), a_(m * m, 0.0) {}
    double &operator()(std::size_t i, std::size_t j) { return a_[i * m_ + j]; }
    bool factor() {
        for (std::size_t j = 0; j < m_; ++j) {
            double d = (*this)(j, j);
            for (std::size_t k = 0; k < j; ++k) d -= (*this)(j, k) * (*this)(j, k);
            if (!(d > 0.0)) return false;
            d = std::sqrt(d);
            (*this)(j, j) = d;
            for (std::size_t i = j + 1; i < m_; ++i) {
                double s = (*this)(i, j);
                for (std::size_t k = 0; k < j; ++k) s -= (*this)(i, k) * (*this)(j, k);
                (*this)(i, j) = s / d;
            }
        }
        return true;
    }
    void solve(std::vector<double> &b) {
        for (std::size_t i = 0; i < m_; ++i) {
            double s = b[i];
            for (std::size_t k = 0; k < i; ++k) s -= (*this)(i, k) * b[k];
            b[i] = s / (*this)(i, i);
        }
        for (std::size_t i = m_; i-- > 0;) {
            double s = b[i];
            for (std::size_t k = i + 1; k < m_; ++k) s -= (*this)(k, i) * b[k];
            b[i] = s / (*this)(i, i);
        }
    }

  private:
    std::size_t m_;
    std::vector<double> a_;
};

std::optional<double> cook_tip(HyconElementKind kind, std::size_t n) {
    const HyconMaterial material{1.0, 1.0 / 3.0, 1.0, HYCON_PLANE_STRESS};
    const CookMesh mesh(n);
    std::vector<long> eq(2 * mesh.nodes(), -1);  // dof -> equation, -1 if clamped
    long n_free = 0;
    for (std::size_t j = 0; j <= n; ++j)
        for (std::size_t i = 1; i <= n; ++i)
            for (std::size_t c = 0; c < 2; ++c) eq[2 * mesh.id(i, j) + c] = n_free++;

    DenseSpd k{static_cast<std::size_t>(n_free)};
    std::vector<double> f(std::size_t(n_free), 0.0);
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t i = 0; i < n; ++i) {
            const std::array<std::array<std::size_t, 2>, 4> corners{
                {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}};  // counter-clockwise
            std::array<double, 8> coords{};
            std::array<long, 8> dofs{};
            for (std::size_t a = 0; a < 4; ++a) {
                const auto [ci, cj] = corners[a];
                const Point p = mesh.at(ci, cj);
                coords[2 * a] = p.x;
                coords[2 * a + 1] = p.y;
                dofs[2 * a] = eq[2 * mesh.id(ci, cj)];
                dofs[2 * a + 1] = eq[2 * mesh.id(ci, cj) + 1];
            }
            std::array<double, 64> ke{};
            CHECK(hycon_element_stiffness(kind, 4, coords.data(), &material, ke.data(), ke.size()));
            for (std::size_t a = 0; a < 8; ++a)
                for (std::size_t b = 0; b < 8; ++b)
                    if (dofs[a] >= 0 && dofs[b] >= 0)
                        k(std::size_t(dofs[a]), std::size_t(dofs[b])) += ke[a * 8 + b];
        }
    }
    for (std::size_t j = 0; j < n; ++j) {  // total shear 1: 1/n per segment, half to each end
        f[std::size_t(eq[2 * mesh.id(n, j) + 1])] += 0.5 / double(n);
        f[std::size_t(eq[2 * mesh.id(n, j + 1) + 1])] += 0.5 / double(n);
    }
    if (!k.factor()) return std::nullopt;
    k.solve(f);
    return f[std::size_t(eq[2 * mesh.id(n, n / 2) + 1])];
}

struct Published {
    std::size_t n;
    double q4, ps;
};

}  // namespace

int main(int argc, char **argv) {
    constexpr std::array<Published, 4> published{
        {{2, 11.845, 21.129}, {4, 18.299, 23.022}, {8, 22.079, 23.689}, {16, 23.430, 23.883}}};
    constexpr double converged = 23.96, rel_tol = 5e-4;
    const std::size_t max_n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 16;
    int failures = 0;
    auto expect = [&failures](bool ok, const char *what, std::size_t n, double got) {
        if (!ok) {
            std::fprintf(stderr, "%s %zux%zu: %.5f is wrong\n", what, n, n, got);
            ++failures;
        }
    };

    std::printf("%4s %10s %10s %10s\n", "n", "Q4", "P-S", "hybrid");
    for (const auto &row : published) {
        if (row.n > max_n) break;
        const auto q4 = cook_tip(HYCON_ELEMENT_Q4, row.n);
        const auto ps = cook_tip(HYCON_ELEMENT_PIAN_SUMIHARA, row.n);
        const auto hy = cook_tip(HYCON_ELEMENT_HYBRID, row.n);
        if (!q4 || !ps || !hy) {
            std::fprintf(stderr, "%zux%zu: stiffness not positive definite\n", row.n, row.n);
            return EXIT_FAILURE;
        }
        std::printf("%4zu %10.4f %10.4f %10.4f\n", row.n, *q4, *ps, *hy);
        expect(std::fabs(*q4 / row.q4 - 1.0) < rel_tol, "Q4", row.n, *q4);
        expect(std::fabs(*ps / row.ps - 1.0) < rel_tol, "Pian-Sumihara", row.n, *ps);
        expect(*hy > *q4 && *hy < *ps, "hybrid (between Q4 and P-S)", row.n, *hy);
        if (row.n == 16)
            expect(std::fabs(*hy / converged - 1.0) < 0.02, "hybrid (2% of 23.96)", row.n, *hy);
    }
    if (failures != 0) {
        std::fprintf(stderr, "%d wrong value(s)\n", failures);
        return EXIT_FAILURE;
    }
    std::printf("OK\n");
    return EXIT_SUCCESS;
}
