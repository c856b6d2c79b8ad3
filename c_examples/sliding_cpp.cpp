// Frictional sliding of a half disk on a block, driven from C++17 through the model API with the
// RAII wrapper include/hycon.hpp (issue 4c).
//
// Set-up (plane strain, E = 1, nu = 0.3 for both bodies, 4-node hybrid elements, mu = 0.3):
// half disk of radius R = 1 (lowest point at the origin) on the block [-2, 2] x [-2, 0], fixed
// on its bottom face; quadrilateral meshes graded toward the contact (sliding_mesh.hpp), element
// size h = a / n on the block's top where the contact travels and on the disk's arc
// (a = R / 16 the Hertz half-width of the load below, n elements per half-width). The block's
// top face is the multiplier side A, the disk's arc the side B. The disk's flat top face is tied
// to a rigid plate: its y translation is force-controlled with the Hertz load
// P = pi a^2 E* / (4 R) (the disk is held only by the plate and by the contact), its x
// translation displacement-controlled. Increments 1 and 2 press (P / 2, P); the next ones move
// the plate sideways (+x) by s = 0.005 a .. 0.05 a (partial slip, Cattaneo-Mindlin: the stick
// zone shrinks, Q grows), then 0.1 a .. 2 a (gross sliding).
//
// Checked at every increment (a failure prints FAILED and the program exits nonzero):
// * slip nodes: |ts| = mu |tn| to 1e-9 relative (the method imposes it exactly);
// * stick nodes: |ts| <= mu |tn| (1 + friction_tolerance);
// * no tension: tn <= 0 at every node, and open nodes carry nothing;
// * slip direction: the block (A) slides backwards relative to the disk, slip_sign = -1 along
//   its tangent +x, and the friction traction ts on the block points forwards (+x);
// * the plate carries the applied force and moves by the prescribed s, the disk's top moves with
//   it; the plate force balances the contact force on A, and the contact forces on A and B are
//   equal and opposite (relative to P, 1e-8); the displacement increment is the difference of
//   the total displacements;
// * partial slip: |Q/P| <= mu and Q grows with s;
// * gross sliding (no stick node): T/N = mu to 1e-9, with T and N the tangential and normal
//   tractions integrated over the interface in its nodal frames; the global resultant Q/P
//   (plate force x / y) within 2% of mu; Q/P is not exactly mu because the friction traction
//   tilts the deformed interface: the half-plane estimate mu - Q/P = (1 - 2 nu)(1 + nu) / E mu
//   8 p0 / (3 pi) = 0.0023 (printed) must hold to 25% (measured 0.98 of it at n = 8, 0.90 at
//   n = 2);
// * the monitor callback (a C++ lambda) saw every iteration record the analysis keeps (and the
//   tries the library's cutback halved, if any); gross sliding is reached and the disk slides
//   2 a.
// The host writes no retry logic: an increment that fails for an iteration reason is taken
// again in sub-increments by the library (HyconContactOptions::cutback_depth); before 0.7.0
// this example halved failed increments itself.
//
// Usage: sliding_cpp [n]   (elements per half-width, 2..64, default 8; 2 for the valgrind run).
// Run time about 0.2 s at n = 8.
#include "hycon.hpp"
#include "sliding_mesh.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr double kMu = 0.3;
constexpr double kSlipLaw = 1e-9;   // relative residual of |ts| = mu |tn| at slip nodes
constexpr double kBalance = 1e-8;   // force balances, relative to P
constexpr double kResultant = 0.02;  // |Q/P - mu| / mu in gross sliding (tilt estimate 0.76%)
constexpr double kTilt = 0.25;       // (mu - Q/P) vs its half-plane estimate, relative

int failures = 0;

void expect(bool ok, const std::string &what) {
    if (!ok) {
        std::fprintf(stderr, "FAILED: %s\n", what.c_str());
        ++failures;
    }
}

// Print the failed call with hycon's status and message and stop.
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

std::string format(const char *fmt, double a, double b = 0.0, double c = 0.0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, fmt, a, b, c);
    return buf;
}

// What one converged increment looks like.
struct Summary {
    std::size_t open = 0, stick = 0, slip = 0;
    double slip_law = 0.0;     // max | |ts| - mu |tn| | / (mu |tn|) over slip nodes
    double stick_ratio = 0.0;  // max |ts| / (mu |tn|) over stick nodes
    double normal = 0.0;       // N = sum w (-tn)
    double tangential = 0.0;   // T = sum w ts
    double force_a[2] = {0.0, 0.0};
};

Summary summarize(const std::vector<HyconNodeResult> &nodes, double step_direction,
                  double friction_tolerance, int step) {
    Summary s;
    double tn_max = 0.0;
    for (const auto &n : nodes) tn_max = std::max(tn_max, std::fabs(n.tn));
    for (const auto &n : nodes) {
        const std::string at = "step " + std::to_string(step) + " node " + std::to_string(n.node);
        expect(n.tn <= 1e-9 * tn_max, at + format(": tension tn = %.3e", n.tn));
        s.normal += -n.tn * n.weight;
        s.tangential += n.ts * n.weight;
        s.force_a[0] += n.force[0];
        s.force_a[1] += n.force[1];
        switch (n.state) {
            case HYCON_NODE_OPEN:
                ++s.open;
                expect(n.tn == 0.0 && n.ts == 0.0, at + ": open node carries a traction");
                break;
            case HYCON_NODE_STICK: {
                ++s.stick;
                const double ratio = std::fabs(n.ts) / (kMu * std::fabs(n.tn));
                s.stick_ratio = std::max(s.stick_ratio, ratio);
                expect(ratio <= 1.0 + friction_tolerance,
                       at + format(": stick node outside the cone, |ts| / mu|tn| = %.15f", ratio));
                break;
            }
            case HYCON_NODE_SLIP: {
                ++s.slip;
                const double residual =
                    std::fabs(std::fabs(n.ts) - kMu * std::fabs(n.tn)) / (kMu * std::fabs(n.tn));
                s.slip_law = std::max(s.slip_law, residual);
                expect(n.tn < 0.0 && residual <= kSlipLaw,
                       at + format(": slip law |ts| = mu |tn| off by %.2e (tn %.3e)", residual,
                                   n.tn));
                if (step_direction != 0.0) {
                    // A (the block) slides backwards relative to the disk, the friction on it
                    // points forwards: slip_sign opposite to the motion along the tangent, ts
                    // along it
                    const double along = n.tangent[0] * step_direction;
                    expect(n.slip_sign * along < 0.0 && n.ts * along > 0.0,
                           at + format(": slip_sign %.0f, ts %.3e, tangent x %.3f inconsistent "
                                       "with the motion",
                                       double(n.slip_sign), n.ts, n.tangent[0]));
                }
                break;
            }
            default:
                expect(false, at + ": unknown state");
        }
    }
    return s;
}

// Counts of the monitor (a C++ lambda) and of the library's cutbacks.
struct Counters {
    std::size_t monitor_calls = 0;  // every iteration record the monitor saw
    std::size_t worst_iteration = 0;
    std::size_t sub_increments = 0;  // over all increments (1 each without cutback)
    std::size_t cutbacks = 0;        // sub-increments the library halved and tried again
};

// The plate's drive: x displacement and y force.
struct Drive {
    double slide = 0.0;
    double force = 0.0;
};

}  // namespace

int main(int argc, char **argv) {
    const auto clock = std::chrono::steady_clock::now();
    const long n_arg = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 8;
    if (n_arg < 2 || n_arg > 64) {
        std::fprintf(stderr, "usage: sliding_cpp [n]   (elements per half-width, 2..64)\n");
        return EXIT_FAILURE;
    }
    const double n = double(n_arg);

    // ---- geometry, materials, load
    const double pi = std::acos(-1.0), radius = 1.0, a = radius / 16.0, h = a / n;
    const double youngs = 1.0, poisson = 0.3;
    const double e_star = youngs / (2.0 * (1.0 - poisson * poisson));  // two equal bodies
    const double load = pi * a * a * e_star / (4.0 * radius);          // Hertz load for a
    const double p0 = 2.0 * load / (pi * a);                           // Hertz peak pressure
    const double tilt =
        (1.0 - 2.0 * poisson) * (1.0 + poisson) / youngs * kMu * 8.0 * p0 / (3.0 * pi);
    const double travel = 3.0;  // the block's fine zone reaches 2 + travel half-widths right
    const double grading = 1.25, h_max = 0.15;
    // The disk's arc has the block top's element size: nodes of the two surfaces nearly face
    // each other, the configuration where edge nodes sit at zero gap and zero traction.
    const double disk_h = h;

    sliding::Mesh mesh;
    const sliding::Block block = sliding::add_block(mesh, 2.0 * radius, 2.0 * radius, -2.0 * a,
                                                    (2.0 + travel) * a, h, grading, h_max, 0);
    const sliding::Disk disk =
        sliding::add_half_disk(mesh, radius, 2.0 * a, disk_h, grading, h_max, 1);
    std::vector<std::size_t> a_side, b_side;  // contact candidates
    for (std::size_t id : block.top)
        if (mesh.x(id) >= -2.5 * a && mesh.x(id) <= (2.5 + travel) * a) a_side.push_back(id);
    for (std::size_t id : disk.arc)
        if (std::fabs(mesh.x(id)) <= 3.0 * a) b_side.push_back(id);
    const HyconMaterial steel_like{youngs, poisson, 1.0, HYCON_PLANE_STRAIN};
    const HyconMaterial materials[2] = {steel_like, steel_like};  // block, disk

    // ---- the model
    hycon::Model model =
        take(hycon::Model::create(mesh.coords, mesh.offsets, mesh.nodes, materials,
                                  HYCON_ELEMENT_HYBRID, mesh.materials),
             "Model::create");
    require(model.prescribe(block.bottom, HYCON_XY), "Model::prescribe");
    const std::size_t pair = take(model.add_pair(a_side, b_side, kMu), "Model::add_pair");
    require(model.set_plate(disk.top), "Model::set_plate");

    // ---- the analysis, with a monitor lambda (it must outlive `contact`: declared first)
    Counters counters;
    auto monitor = [&counters](const HyconIterationRecord &r) {
        ++counters.monitor_calls;
        counters.worst_iteration = std::max(counters.worst_iteration, std::size_t(r.iteration));
        return true;  // go on
    };
    // the disk slides over many elements: finite kinematics
    HyconContactOptions options = hycon::default_options(HYCON_KINEMATICS_FINITE);
    options.tolerance = 1e-10;
    hycon::set_monitor(options, monitor);
    hycon::Contact contact = take(hycon::Contact::create(model, options), "Contact::create");
    const std::vector<double> zeros(take(contact.field_len(), "field_len"), 0.0);

    std::printf("frictional sliding, mu = %.2f: half disk R = %.0f on a block, %zu nodes, %zu "
                "elements, h = a / %ld = %.3e (disk arc %.3e), %zu A and %zu B nodes\n",
                kMu, radius, mesh.node_count(), mesh.element_count(), n_arg, h, disk_h,
                a_side.size(), b_side.size());
    std::printf("plate: y force -P, P = %.6e (Hertz load for a = R/16), x displacement s; "
                "half-plane tilt estimate of mu - Q/P in gross sliding: %.5f\n",
                load, tilt);
    std::printf("%4s %7s %8s %3s %4s %5s %4s %9s %8s %9s %8s %8s %14s %9s\n", "step", "P/Phz",
                "s/a", "it", "act", "stick", "slip", "Q/P", "slip law", "stick max", "FA-plate",
                "FA+FB", "T/N - mu", "tilt");

    // press in 2 increments, then slide: partial slip up to about s = 0.06 a, then gross sliding
    std::vector<Drive> path = {{0.0, -0.5 * load}, {0.0, -load}};
    for (double s : {0.005, 0.01, 0.02, 0.03, 0.04, 0.05, 0.1, 0.5, 1.0, 1.5, 2.0})
        path.push_back({s * a, -load});
    Drive current;
    std::vector<double> previous_u(zeros.size(), 0.0);
    bool sliding_reached = false;
    double previous_q_over_p = 0.0, worst_slip_law = 0.0;
    int step = 0;
    for (const Drive &drive : path) {
        ++step;
        // no retry logic here: an increment that fails for an iteration reason is taken again
        // in sub-increments by the library (options.cutback_depth), still one increment
        const HyconIncrementInfo info = take(
            contact.increment_with_plate(zeros, zeros, hycon::plate_displacement(drive.slide),
                                         hycon::plate_force(drive.force)),
            "increment_with_plate");
        counters.sub_increments += info.sub_increments;
        counters.cutbacks += info.cutbacks;
        if (info.sub_increments > 1)
            std::printf("     (the library took it in %zu sub-increments)\n", info.sub_increments);
        const double direction = drive.slide > current.slide   ? 1.0
                                 : drive.slide < current.slide ? -1.0
                                                               : 0.0;
        current = drive;
        const auto nodes = take(contact.node_results(pair), "Contact::node_results");
        const auto b_nodes = take(contact.b_node_results(pair), "Contact::b_node_results");
        const hycon::PlateState plate = take(contact.plate(), "Contact::plate");
        const auto u = take(contact.displacement(), "Contact::displacement");
        const auto du = take(contact.displacement_increment(), "Contact::displacement_increment");

        const Summary sum = summarize(nodes, direction, options.friction_tolerance, step);
        double force_b[2] = {0.0, 0.0};
        for (const auto &b : b_nodes) {
            force_b[0] += b.force[0];
            force_b[1] += b.force[1];
        }
        const double p = -plate.force[1], q_over_p = plate.force[0] / p;
        const double t_over_n = sum.tangential / sum.normal;
        const double plate_balance =
            std::hypot(sum.force_a[0] - plate.force[0], sum.force_a[1] - plate.force[1]) / p;
        const double action_reaction =
            std::hypot(sum.force_a[0] + force_b[0], sum.force_a[1] + force_b[1]) / p;
        const bool gross = sum.stick == 0 && sum.slip > 0;
        const double deficit = (kMu - q_over_p) / tilt;  // meaningful in gross sliding
        char gross_columns[64] = "";  // T/N - mu and the tilt ratio, in gross sliding only
        if (gross)
            std::snprintf(gross_columns, sizeof gross_columns, " %+14.3e %9.3f", t_over_n - kMu,
                          deficit);
        std::printf("%4d %7.4f %8.4f %3zu %4zu %5zu %4zu %9.6f %8.1e %9.6f %8.1e %8.1e%s\n",
                    step, p / load, drive.slide / a, info.iterations, info.active, sum.stick,
                    sum.slip, q_over_p, sum.slip_law, sum.stick_ratio, plate_balance,
                    action_reaction, gross_columns);

        const std::string at = "step " + std::to_string(step);
        expect(info.active == sum.stick + sum.slip && info.slip == sum.slip,
               at + ": increment info disagrees with the node results");
        expect(std::fabs(p / -drive.force - 1.0) < 1e-9,
               at + format(": plate force %.9e, applied %.9e", p, -drive.force));
        expect(std::fabs(plate.displacement[0] - drive.slide) <= 1e-12 * a,
               at + format(": plate x displacement %.6e, prescribed %.6e", plate.displacement[0],
                           drive.slide));
        expect(plate_balance < kBalance,
               at + format(": plate force vs contact force on A: %.2e P", plate_balance));
        expect(action_reaction < kBalance,
               at + format(": contact forces on A and B not opposite: %.2e P", action_reaction));
        expect(sum.stick + sum.slip > 0, at + ": the disk is not in contact");
        // the displacement field: the disk's top moves with the plate, and the increment is the
        // difference of the totals (also when the library took it in sub-increments)
        double top_error = 0.0, u_max = 0.0, du_error = 0.0;
        for (std::size_t id : disk.top)
            top_error = std::max(top_error, std::fabs(u[2 * id] - plate.displacement[0]) +
                                                std::fabs(u[2 * id + 1] - plate.displacement[1]));
        for (std::size_t i = 0; i < u.size(); ++i) {
            u_max = std::max(u_max, std::fabs(u[i]));
            du_error = std::max(du_error, std::fabs(u[i] - previous_u[i] - du[i]));
        }
        previous_u = u;
        expect(top_error <= 1e-12 * u_max,
               at + format(": the disk's top is off the plate by %.2e", top_error));
        expect(du_error <= 1e-9 * u_max,
               at + format(": displacement increment off by %.2e of max |u|", du_error / u_max));
        if (gross) {
            sliding_reached = true;
            expect(std::fabs(t_over_n / kMu - 1.0) < kSlipLaw,
                   at + format(": T/N = %.12f in gross sliding, mu = %.2f", t_over_n, kMu));
            expect(std::fabs(q_over_p / kMu - 1.0) < kResultant,
                   at + format(": Q/P = %.6f in gross sliding, mu = %.2f", q_over_p, kMu));
            expect(std::fabs(deficit - 1.0) < kTilt,
                   at + format(": mu - Q/P is %.3f of the tilt estimate", deficit));
        } else {
            expect(std::fabs(q_over_p) <= kMu, at + format(": |Q/P| = %.6f > mu", q_over_p));
            // before gross sliding the friction force grows with s (Cattaneo-Mindlin)
            if (direction > 0.0)
                expect(q_over_p > previous_q_over_p,
                       at + format(": Q/P = %.6f did not grow (%.6f before)", q_over_p,
                                   previous_q_over_p));
        }
        previous_q_over_p = q_over_p;
        worst_slip_law = std::max(worst_slip_law, sum.slip_law);
    }
    expect(sliding_reached && current.slide >= 2.0 * a,
           "the disk did not slide 2 a in gross sliding");

    const auto records = take(contact.records(), "Contact::records");
    // the analysis keeps the records of converged sub-increments; the monitor also saw the
    // tries the cutback halved
    expect(counters.cutbacks == 0 ? records.size() == counters.monitor_calls
                                  : records.size() < counters.monitor_calls,
           format("the monitor saw %.0f records, the analysis kept %.0f (%.0f cutbacks)",
                  double(counters.monitor_calls), double(records.size()),
                  double(counters.cutbacks)));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
    std::printf("slip law residual at most %.1e (tolerance %.0e); monitor: %zu iteration records, "
                "at most %zu iterations in an increment; %zu sub-increments for %zu increments "
                "(%zu cutbacks); run time %.2f s\n",
                worst_slip_law, kSlipLaw, counters.monitor_calls, counters.worst_iteration,
                counters.sub_increments, path.size(), counters.cutbacks, seconds);
    if (failures != 0) {
        std::fprintf(stderr, "%d check(s) FAILED\n", failures);
        return EXIT_FAILURE;
    }
    std::printf("OK\n");
    return EXIT_SUCCESS;
}
