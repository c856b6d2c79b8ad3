// Compile check and smoke test of include/hycon.hpp (issue 4d): the wrapper alone (it includes
// hycon.h itself), included twice, clean C++17 under -Wall -Wextra -Werror -pedantic; built
// twice by CMake, with and without -fno-exceptions (target header_hpp17_noexcept).
//
// At run time it exercises what the sliding example does not: the solve-callback adapter
// (host-assembly API with a diagonal K solved by a C++ lambda), a monitor that stops the
// increment (the state is kept), Status messages from the wrapper's own length checks and from
// hycon, the condensed hand-over (contact_equations, set_condensed: the same displacement
// recovered from the contact forces), and, with exceptions enabled, a throwing callback that
// must not unwind into hycon.
//
// The host problem: body A's top face (nodes 0, 1 at y = 0) and body B's bottom face (nodes
// 2, 3 at y = g = 0.01) over x in [0, 1], every dof on a unit spring to the ground (K = I,
// 8 equations), B pushed down by 0.1 per node, frictionless. Matching segments close with equal
// nodal forces f: 0.01 + (-0.1 + f) - (-f) = 0, so f = 0.045, v_A = -0.045, v_B = -0.055.
#include "hycon.hpp"
#include "hycon.hpp"  // twice on purpose: the include guard must hold

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// ---- compile-time checks of the wrapper's types
static_assert(!std::is_copy_constructible_v<hycon::Contact>, "handles are move-only");
static_assert(!std::is_copy_assignable_v<hycon::Model>, "handles are move-only");
static_assert(std::is_nothrow_move_constructible_v<hycon::Contact>, "handles move cheaply");
static_assert(std::is_nothrow_move_assignable_v<hycon::Host>, "handles move cheaply");
static_assert(sizeof(hycon::ContactPtr) == sizeof(HyconContact *), "empty deleters");
static_assert(sizeof(hycon::ModelPtr) == sizeof(HyconModel *), "empty deleters");
static_assert(sizeof(hycon::HostPtr) == sizeof(HyconHost *), "empty deleters");
static_assert(std::is_same_v<decltype(std::declval<hycon::Contact &>().node_results(0)),
                             hycon::Result<std::vector<HyconNodeResult>>>,
              "node results come back as a vector");
static_assert(std::is_convertible_v<std::vector<double>, hycon::View<double>>, "views");
static_assert(std::is_convertible_v<double (&)[4], hycon::View<double>>, "views");
static_assert(!std::is_convertible_v<std::vector<int>, hycon::View<double>>, "views are typed");

// set_monitor and set_solver take lvalues only (the library keeps a pointer to the callable).
template <class F, class = void>
struct can_monitor : std::false_type {};
template <class F>
struct can_monitor<F, std::void_t<decltype(hycon::set_monitor(
                          std::declval<HyconContactOptions &>(), std::declval<F>()))>>
    : std::true_type {};
struct MonitorObject {
    bool operator()(const HyconIterationRecord &) const { return true; }
};
static_assert(can_monitor<MonitorObject &>::value, "an lvalue callable is accepted");
static_assert(!can_monitor<MonitorObject>::value, "a temporary is refused");
static_assert(!can_monitor<const MonitorObject>::value, "a const temporary is refused");

namespace {

int failures = 0;

void expect(bool ok, const char *what) {
    if (!ok) {
        std::fprintf(stderr, "FAILED: %s\n", what);
        ++failures;
    }
}

// The host's polylines and its diagonal stiffness.
constexpr double kGap = 0.01, kPush = 0.1;

hycon::Result<hycon::Host> make_host() {
    auto host = hycon::Host::create(8);
    if (!host) return host;
    const std::size_t a_nodes[2] = {0, 1}, b_nodes[2] = {2, 3};  // A right to left, B left to right
    const double a_coords[4] = {1.0, 0.0, 0.0, 0.0}, b_coords[4] = {0.0, kGap, 1.0, kGap};
    const std::int64_t a_eq[4] = {0, 1, 2, 3}, b_eq[4] = {4, 5, 6, 7};
    const auto pair = host->add_pair(a_nodes, a_coords, a_eq, b_nodes, b_coords, b_eq, 0.0,
                                     HYCON_PLANE_STRAIN, 1.0);
    if (!pair) return hycon::Result<hycon::Host>(pair.status());
    // the surfaces lie within half a segment: say which side body A is on (below A)
    const hycon::Status side = host->set_pair_inside(*pair, {0.5, -0.5});
    if (!side) return hycon::Result<hycon::Host>(side);
    return host;
}

// The condensed hand-over through the wrapper (Host::contact_equations, Host::set_condensed,
// Contact::forces) on the same host problem: with K = I the Schur complement over the contact
// equations (here all 8) is I, the load image u0 = K^-1 load is the load at them, and the host
// recovers u = K^-1 (load + forces) = load + forces, which must be the callback path's `u`.
void condensed_hand_over(const std::vector<double> &load, const std::vector<double> &u) {
    auto host = make_host();
    const auto equations = host ? host->contact_equations()
                                : hycon::Result<std::vector<std::int64_t>>(host.status());
    if (!equations || equations->size() != 8) {
        expect(false, "contact_equations lists the 8 equations of the contact nodes");
        return;
    }
    const std::size_t m = equations->size();
    std::vector<double> schur(m * m, 0.0), image(m);
    for (std::size_t i = 0; i < m; ++i) {
        schur[i * (m + 1)] = 1.0;
        image[i] = load[static_cast<std::size_t>((*equations)[i])];
    }
    expect(host->set_condensed(HYCON_CONDENSED_STIFFNESS, *equations, image).code() ==
               HYCON_ERROR_INVALID_ARGUMENT,
           "set_condensed checks the matrix size");
    expect(host->set_condensed(HYCON_CONDENSED_STIFFNESS, *equations, schur).ok(),
           "set_condensed");
    auto contact = hycon::Contact::create(*host);
    const auto info = contact ? contact->increment(image)
                              : hycon::Result<HyconIncrementInfo>(contact.status());
    const auto forces =
        info ? contact->forces() : hycon::Result<std::vector<double>>(info.status());
    double difference = forces && forces->size() == u.size() ? 0.0 : 1.0;
    for (std::size_t i = 0; difference < 1.0 && i < u.size(); ++i)
        difference = std::fmax(difference, std::fabs(load[i] + (*forces)[i] - u[i]));
    expect(info && info->active == 2 && difference < 1e-12,
           "the condensed path recovers the callback path's displacement");
    expect(contact && !contact->displacement(), "a condensed analysis has no displacement");
    std::printf("condensed hand-over: %zu contact equations, recovered displacement within "
                "%.1e of the callback path's\n",
                m, difference);
}

// The 3D model family through hycon::SolidModel and hycon::SolidContact: two unit cubes of one
// hybrid brick each, A (nodes 0-7) on B (nodes 8-15), B's bottom held, A's top moved down by
// 1e-3, frictionless; every member of SolidContact called once.
void solid_two_cubes() {
    static const double unit[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    std::vector<double> coords;
    for (int cube = 0; cube < 2; ++cube)
        for (const auto &p : unit)
            for (int d = 0; d < 3; ++d) coords.push_back(p[d] + (d == 2 && cube == 0 ? 1.0 : 0.0));
    std::vector<std::size_t> bricks(16);
    for (std::size_t i = 0; i < 16; ++i) bricks[i] = i;
    const HyconSolidMaterial steel[1] = {{210e3, 0.3}};
    const auto short_bricks = hycon::SolidModel::create(
        coords, std::vector<std::size_t>(bricks.begin(), bricks.end() - 1), steel,
        HYCON_BRICK_HYBRID18);
    expect(short_bricks.code() == HYCON_ERROR_INVALID_ARGUMENT,
           "SolidModel::create checks 8 ids per brick");
    auto model = hycon::SolidModel::create(coords, bricks, steel, HYCON_BRICK_HYBRID18);
    expect(static_cast<bool>(model), "SolidModel::create");
    if (!model) return;
    const std::size_t top[4] = {4, 5, 6, 7}, bottom[4] = {8, 9, 10, 11};
    expect(model->prescribe(bottom, HYCON_XYZ).ok() && model->prescribe(top, HYCON_XYZ).ok(),
           "SolidModel::prescribe");
    const hycon::BrickFace a[1] = {{0, 4}}, b[1] = {{1, 5}};
    const auto pair = model->add_pair(a, b, 0.0);
    expect(pair && *pair == 0, "SolidModel::add_pair");
    auto contact = hycon::SolidContact::create(*model);
    expect(static_cast<bool>(contact), "SolidContact::create");
    if (!contact) return;
    hycon::SolidContact c = std::move(contact.value());
    const auto n = c.field_len();
    expect(n && *n == 48, "field length 3 n_nodes");
    std::vector<double> load(48, 0.0), prescribed(48, 0.0);
    for (std::size_t k : top) prescribed[3 * k + 2] = -1e-3;
    const auto info = c.increment(load, prescribed);
    expect(info && info->active == 4, "the press closes A's 4 nodes");
    const auto size = c.pair_size(0);
    const auto nodes = c.node_results(0);
    const auto b_nodes = c.b_node_results(0);
    const auto surface = c.surface_nodes(0);
    const auto u = c.displacement();
    const auto du = c.displacement_increment();
    const auto forces = c.forces();
    const auto records = c.records();
    const auto timings = c.timings();
    const auto kc = c.constraint_rows(0);
    const auto coupling = c.surface_coupling(0);
    bool ok = size && size->a == 4 && size->b == 4 && nodes && b_nodes && surface && u && du &&
              *u == *du && forces && forces->size() == 48 && records && !records->empty() &&
              timings && timings->factorizations == 1 && kc && kc->back().row == 11 &&
              coupling && !coupling->empty();
    double fz = 0.0;
    for (std::size_t i = 0; ok && i < 4; ++i) {
        const HyconSolidNodeResult &r = (*nodes)[i];
        ok = r.state == HYCON_NODE_FRICTIONLESS && r.tn < 0.0 && r.normal[2] == -1.0 &&
             std::fabs(r.force[2] + (*b_nodes)[i].force[2]) < 1e-12 * std::fabs(r.force[2]);
        fz += r.force[2];
    }
    expect(ok && fz > 0.0, "SolidContact results: frictionless, pressed, balanced");
    std::printf("two cubes: %zu A nodes, force on A %.6e\n", nodes ? nodes->size() : 0, fz);
}

}  // namespace

int main() {
    // ---- version and defaults
    const auto version = hycon::version();
    expect(version && (*version)[0] == HYCON_VERSION_MAJOR &&
               (*version)[1] == HYCON_VERSION_MINOR && (*version)[2] == HYCON_VERSION_PATCH,
           "library version matches the header");
    const HyconContactOptions defaults = hycon::default_options();
    expect(defaults.tolerance > 0.0 && defaults.max_iterations > 0 && defaults.monitor == nullptr,
           "default options");
    expect(defaults.kinematics == HYCON_KINEMATICS_SMALL &&
               hycon::default_options(HYCON_KINEMATICS_FINITE).kinematics ==
                   HYCON_KINEMATICS_FINITE,
           "default kinematics and the kinematics overload");

    // ---- errors: the wrapper's own length checks and hycon's messages
    {
        const std::vector<double> odd = {0.0, 0.0, 1.0};
        const std::vector<std::size_t> offsets = {0, 4}, nodes = {0, 1, 2, 3};
        const HyconMaterial material{1.0, 0.3, 1.0, HYCON_PLANE_STRAIN};
        const HyconMaterial materials[1] = {material};
        auto bad = hycon::Model::create(odd, offsets, nodes, materials, HYCON_ELEMENT_HYBRID);
        expect(!bad && bad.code() == HYCON_ERROR_INVALID_ARGUMENT && !bad.message().empty() &&
                   !bad.value(),
               "odd coordinate count refused by the wrapper");
        const std::vector<double> clockwise = {0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0};
        auto inverted =
            hycon::Model::create(clockwise, offsets, nodes, materials, HYCON_ELEMENT_HYBRID);
        expect(!inverted && inverted.code() == HYCON_ERROR_BAD_ELEMENT &&
                   inverted.message().find("element 0") != std::string::npos,
               "clockwise element refused by hycon, with its message");
        std::printf("expected errors: %s: %s\n                 %s: %s\n", bad.status().name(),
                    bad.message().c_str(), inverted.status().name(), inverted.message().c_str());
        const hycon::Status ok;
        expect(ok.ok() && ok.code() == HYCON_OK && ok.message().empty(), "default Status is OK");
        expect(hycon::Status(1, "").ok(), "warnings count as success");
        expect(!hycon::element_check(HYCON_ELEMENT_Q4, clockwise), "element_check");
        const auto k = hycon::element_stiffness(
            HYCON_ELEMENT_Q4, std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1}, material);
        expect(k && k->size() == 64 && std::fabs((*k)[0] - (*k)[63]) < 1e-12 * std::fabs((*k)[0]),
               "element_stiffness");
    }

    // ---- host-assembly API with the solve adapter and the monitor adapter
    std::size_t solves = 0, columns = 0, records_seen = 0;
    auto solve = [&](std::size_t n, std::size_t nrhs, const double *rhs, double *x) {
        ++solves;
        columns += nrhs;
        for (std::size_t i = 0; i < n * nrhs; ++i) x[i] = rhs[i];  // K = I
        return true;
    };
    bool keep_going = true;
    auto monitor = [&](const HyconIterationRecord &) {
        ++records_seen;
        return keep_going;
    };
    auto host = make_host();
    expect(static_cast<bool>(host), "host description");
    expect(host->set_solver(solve).ok(), "set_solver from a lambda");
    expect(host->set_csr(std::vector<std::size_t>{0, 1}, std::vector<std::size_t>{0},
                         std::vector<double>{1.0}, HYCON_CSR_FULL)
                   .code() == HYCON_ERROR_INVALID_ARGUMENT,
           "set_csr checks the row_ptr length");
    HyconContactOptions options = hycon::default_options();
    hycon::set_monitor(options, monitor);
    auto contact = hycon::Contact::create(*host, options);
    host = hycon::Result<hycon::Host>(hycon::Host());  // the analysis keeps its own copy
    expect(static_cast<bool>(contact), "contact analysis from the host");
    // the flexibility is built as nodes enter: at the start only the nearest A node's
    // directions, fewer columns than the 8 contact dofs
    expect(solves > 0 && columns >= 1 && columns < 8,
           "the solve lambda gave the first node's flexibility columns");
    std::vector<double> load(8, 0.0);
    load[5] = load[7] = -kPush;

    // a monitor that stops the increment: HYCON_ERROR_CALLBACK, the state is kept
    keep_going = false;
    const auto stopped = contact->increment(load);
    expect(stopped.code() == HYCON_ERROR_CALLBACK && records_seen == 1,
           "a monitor returning false stops the increment");
    const auto before = contact->displacement();
    expect(before && before->size() == 8 && (*before)[5] == 0.0, "state kept after the failure");

    keep_going = true;
    const auto info = contact->increment(load);
    expect(info && info->active == 2, "the increment closes both A nodes");
    const auto u = contact->displacement();
    const auto du = contact->displacement_increment();  // the first increment: the total
    expect(u && du && *u == *du, "displacement increment of the first increment");
    const auto nodes = contact->node_results(0);
    const auto records = contact->records();
    const double f = 0.5 * (kPush - kGap);
    bool close = u && u->size() == 8 && nodes && nodes->size() == 2;
    if (close) {
        const std::vector<double> &v = *u;
        close = std::fabs(v[1] + f) < 1e-9 && std::fabs(v[3] + f) < 1e-9 &&  // A down by f
                std::fabs(v[5] + kPush - f) < 1e-9 && std::fabs(v[7] + kPush - f) < 1e-9 &&
                std::fabs(v[0]) + std::fabs(v[2]) + std::fabs(v[4]) + std::fabs(v[6]) < 1e-9;
        double fy = 0.0;
        for (const auto &n : *nodes) fy += n.force[1];
        close = close && std::fabs(fy + 2.0 * f) < 1e-9;  // the force on A, downwards
    }
    expect(close, "displacements and contact forces of the host problem");
    expect(records && records->size() + 1 == records_seen,
           "records of converged increments only (the stopped one is excluded)");
    const auto kc = contact->constraint_rows(0);
    bool ordered = kc && !kc->empty() && kc->back().row < 4;
    for (std::size_t i = 1; ordered && i < kc->size(); ++i) {
        const HyconConstraintEntry &p = (*kc)[i - 1], &e = (*kc)[i];
        ordered = p.row < e.row || (p.row == e.row && p.column < e.column);
    }
    expect(ordered, "Kc entries row-major, columns ascending, 2 n_a = 4 rows");
    const auto coupling = contact->surface_coupling(0);
    expect(coupling && !coupling->empty(), "coupling entries");
    std::printf("host problem: v_A = %.6f, v_B = %.6f (expected %.6f, %.6f); %zu solve calls "
                "with %zu columns; %zu monitor calls\n",
                u && u->size() == 8 ? (*u)[1] : 0.0, u && u->size() == 8 ? (*u)[5] : 0.0, -f,
                -(kPush - f), solves, columns, records_seen);

    if (u) condensed_hand_over(load, *u);

    solid_two_cubes();

    // the load and check helpers: a unit pressure on edge 1 of the unit square (1/2 each end,
    // along -x), its area, quality 1; a cube's bottom face pushed by 2 (2 in all along +z)
    {
        const std::vector<double> square = {0, 0, 1, 0, 1, 1, 0, 1};
        const HyconMaterial plane = {1000.0, 0.3, 1.0, HYCON_PLANE_STRAIN};
        const double unit[2] = {1.0, 1.0};
        const auto fe = hycon::element_edge_load(HYCON_ELEMENT_Q4, square, plane, 1, unit, {});
        expect(fe && fe->size() == 8 && (*fe)[2] == -0.5 && (*fe)[4] == -0.5,
               "element_edge_load");
        const auto v = hycon::element_volume(HYCON_ELEMENT_Q4, square, plane);
        const auto q = hycon::element_quality(HYCON_ELEMENT_HYBRID, square);
        expect(v && *v == 1.0 && q && *q == 1.0, "element_volume, element_quality");
        const double one[1] = {1.0};
        const auto bad = hycon::element_edge_load(HYCON_ELEMENT_Q4, square, plane, 1, one, {});
        expect(bad.code() == HYCON_ERROR_INVALID_ARGUMENT, "a pressure of 1 value is refused");
        const std::array<double, 24> cube = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                             0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
        const double two[4] = {2.0, 2.0, 2.0, 2.0};
        const auto fb = hycon::brick_face_load(HYCON_BRICK_H8, cube, 4, two, {});
        double fz = 0.0;
        for (std::size_t k = 0; fb && k < 8; ++k) fz += (*fb)[3 * k + 2];
        expect(fb && std::fabs(fz - 2.0) < 1e-14, "brick_face_load");
        const auto vb = hycon::brick_volume(HYCON_BRICK_H8, cube);
        const auto qb = hycon::brick_quality(HYCON_BRICK_H8, cube);
        expect(vb && std::fabs(*vb - 1.0) < 1e-14 && qb && std::fabs(*qb - 1.0) < 1e-14,
               "brick_volume, brick_quality");
        const std::array<double, 24> zero{};
        const auto sb = hycon::brick_stress_natural(HYCON_BRICK_HYBRID18, cube, {1000.0, 0.3},
                                                    zero, {0.5, -0.5, 1.0});
        const auto s2 = hycon::element_stress_natural(HYCON_ELEMENT_HYBRID, square, plane,
                                                      std::vector<double>(8, 0.0), 1.0, -1.0);
        expect(sb && (*sb)[0] == 0.0 && s2 && s2->size() == 3, "stress at natural coordinates");
    }

#if defined(__cpp_exceptions)
    // a throwing solver must not unwind into hycon: the trampoline reports a failure
    {
        auto throwing = [](std::size_t, std::size_t, const double *, double *) -> bool {
            throw std::string("host solver failure");
        };
        auto other = make_host();
        expect(other && other->set_solver(throwing).ok(), "set_solver");
        const auto failed = hycon::Contact::create(*other);
        expect(failed.code() == HYCON_ERROR_CALLBACK,
               "a throwing solver gives HYCON_ERROR_CALLBACK");
        std::printf("exceptions enabled: a throwing solver gave %s: %s\n", failed.status().name(),
                    failed.message().c_str());
    }
#else
    std::printf("built without exceptions\n");
#endif

    if (failures != 0) {
        std::fprintf(stderr, "%d check(s) FAILED\n", failures);
        return EXIT_FAILURE;
    }
    std::printf("OK\n");
    return EXIT_SUCCESS;
}
