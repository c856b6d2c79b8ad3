// SPDX-License-Identifier: MIT
/*
 * hycon.hpp: a header-only C++17 RAII wrapper over the C API of hycon (include/hycon.h).
 *
 * What it adds to hycon.h, and nothing more:
 * - Ownership: hycon::Model, hycon::Host and hycon::Contact own a HyconModel, HyconHost and
 *   HyconContact through std::unique_ptr with deleters calling hycon_*_free (move-only; an
 *   empty object holds no handle); hycon::SolidModel and hycon::SolidContact own the 3D
 *   family's HyconSolidModel and HyconSolidContact likewise. The raw unique_ptr types are
 *   hycon::ModelPtr, HostPtr, ContactPtr, SolidModelPtr and SolidContactPtr; get() gives the C
 *   handle for calls the wrapper does not cover. The members of Contact and SolidContact whose
 *   meaning does not depend on the dimension (increment, displacement, forces, records, ...)
 *   are written once, in detail::Analysis.
 * - Errors without exceptions: every call returns a [[nodiscard]] hycon::Status (the
 *   HyconStatus and, on an error or a warning, the message of hycon_last_error_message) or a
 *   hycon::Result<T> (a Status and a value). Nothing here throws except std::bad_alloc from
 *   the standard containers, so it builds with -fno-exceptions. ok() is true for HYCON_OK and
 *   for warnings (> 0), as in the C API. Length errors found by the wrapper itself (before any
 *   C call) are HYCON_ERROR_INVALID_ARGUMENT with the wrapper's message; they leave the
 *   thread's last error message alone.
 * - Lengths: arrays go in as hycon::View<T> (a pointer and a length; made implicitly from a
 *   std::vector, std::array or C array) and the wrapper checks the lengths the C
 *   functions take on trust (coordinates pairs, element connectivity, CSR arrays, 2 n
 *   coordinates and equations per host polyline). Results come back as std::vector.
 * - Callbacks from C++ callables: hycon::set_monitor(options, callable) and
 *   Host::set_solver(callable) install a trampoline and a pointer to the callable. The C
 *   library keeps that pointer, so the callable must outlive every Contact that uses it
 *   (temporaries are refused at compile time). No exception crosses into the C library: when
 *   exceptions are enabled the trampoline catches everything and reports a failure, which
 *   hycon turns into HYCON_ERROR_CALLBACK.
 *
 * Thread safety: as the C API's. A non-const member needs its object exclusively; the const
 * queries of a Contact (displacement, node_results, records, ...) may run on one Contact from
 * several threads at once. Objects may move between threads; distinct ones share nothing and
 * may be used from different threads at once. The error message behind a Status is read from the
 * calling thread's last error right after the failing call. Callbacks (monitor, solver) run on
 * the thread that called into the Contact. hycon starts threads of its own only when the
 * options' `threads` (0.6.0) is more than 1, and none outlives the call that started it.
 *
 * Lifetimes: a Contact copies what it needs from its Model or Host (they may be destroyed
 * first), except the callables given to set_monitor and set_solver.
 *
 * Example (model API):
 *
 *     auto model = hycon::Model::create(coords, offsets, nodes, materials, HYCON_ELEMENT_HYBRID);
 *     if (!model) { std::fprintf(stderr, "%s\n", model.status().message().c_str()); return 1; }
 *     ...
 *     auto contact = hycon::Contact::create(model.value(), hycon::default_options());
 *     auto info = contact->increment(load, prescribed);
 *     auto nodes = contact->node_results(0);   // Result<std::vector<HyconNodeResult>>
 */

#ifndef HYCON_HPP
#define HYCON_HPP

#include "hycon.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace hycon {

// ---------------------------------------------------------------------------------------------
// Status and Result

// This thread's last error message (empty after a successful call).
inline std::string last_error_message() {
    const std::size_t needed = hycon_last_error_message(nullptr, 0);  // with the NUL
    if (needed <= 1) return std::string();
    std::string message(needed, '\0');
    (void)hycon_last_error_message(&message[0], message.size());
    message.resize(needed - 1);  // drop the NUL
    return message;
}

// The outcome of a call: its HyconStatus and, for an error, hycon's message.
class [[nodiscard]] Status {
  public:
    // Success.
    Status() noexcept = default;
    Status(HyconStatus code, std::string message) noexcept
        : code_(code), message_(std::move(message)) {}

    // The status of a C call that just returned `code`: for an error or a warning, the message
    // is read from this thread's last error.
    static Status from(HyconStatus code) {
        return code != HYCON_OK ? Status(code, last_error_message()) : Status();
    }

    // Success or a warning (the outputs were written).
    bool ok() const noexcept { return code_ >= 0; }
    explicit operator bool() const noexcept { return ok(); }
    HyconStatus code() const noexcept { return code_; }
    // The constant's name, e.g. "HYCON_ERROR_CONTACT" (a static string).
    const char *name() const noexcept { return hycon_status_name(code_); }
    // hycon's message for an error or a warning, empty otherwise.
    const std::string &message() const noexcept { return message_; }

  private:
    HyconStatus code_ = HYCON_OK;
    std::string message_;
};

// A value and the Status of the call that made it. On an error the value is
// value-initialised (an empty vector, an empty handle, zeros).
template <class T>
class [[nodiscard]] Result {
  public:
    // Success.
    Result(T value) : value_(std::move(value)) {}  // NOLINT: implicit on purpose
    // A failure (or a value with a warning status).
    Result(Status status, T value = T()) : status_(std::move(status)), value_(std::move(value)) {}

    bool ok() const noexcept { return status_.ok(); }
    explicit operator bool() const noexcept { return ok(); }
    const Status &status() const noexcept { return status_; }
    HyconStatus code() const noexcept { return status_.code(); }
    const std::string &message() const noexcept { return status_.message(); }

    T &value() & noexcept { return value_; }
    const T &value() const & noexcept { return value_; }
    T &&value() && noexcept { return std::move(value_); }
    T &operator*() & noexcept { return value_; }
    const T &operator*() const & noexcept { return value_; }
    T &&operator*() && noexcept { return std::move(value_); }
    T *operator->() noexcept { return &value_; }
    const T *operator->() const noexcept { return &value_; }

  private:
    Status status_;
    T value_;
};

namespace detail {

inline Status invalid(const char *message) {
    return Status(HYCON_ERROR_INVALID_ARGUMENT, message);
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------
// View: a read-only (pointer, length) array argument

template <class T>
class View {
  public:
    constexpr View() noexcept = default;
    constexpr View(const T *data, std::size_t size) noexcept : data_(data), size_(size) {}
    // Any contiguous container or array of T: std::vector, std::array, T[N].
    template <class C, class = std::enable_if_t<std::is_convertible_v<
                           decltype(std::data(std::declval<const C &>())), const T *>>>
    constexpr View(const C &c) noexcept  // NOLINT: implicit on purpose
        : data_(std::data(c)), size_(std::size(c)) {}

    // NULL for an empty view, as the C API takes (NULL, 0) for an empty array.
    constexpr const T *data() const noexcept { return size_ == 0 ? nullptr : data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr const T &operator[](std::size_t i) const noexcept { return data_[i]; }
    constexpr const T &back() const noexcept { return data_[size_ - 1]; }

  private:
    const T *data_ = nullptr;
    std::size_t size_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Library-wide functions

// The library's version {major, minor, patch} (compare with HYCON_VERSION_MAJOR etc.).
inline Result<std::array<std::int32_t, 3>> version() {
    std::array<std::int32_t, 3> v{};
    const Status s = Status::from(hycon_version(v.data()));
    return s.ok() ? Result<std::array<std::int32_t, 3>>(v) : Result<std::array<std::int32_t, 3>>(s);
}

// The default contact options (the values documented in hycon.h, no monitor; `size` set, the
// automatic cutback on).
inline HyconContactOptions default_options() noexcept {
    HyconContactOptions options{};
    (void)hycon_contact_options_default(&options);  // cannot fail with a valid pointer
    return options;
}

// The default contact options with the given kinematics: HYCON_KINEMATICS_SMALL (the
// default: geometry evaluated once, linear gap) or HYCON_KINEMATICS_FINITE (extensive sliding).
inline HyconContactOptions default_options(HyconKinematics kinematics) noexcept {
    HyconContactOptions options = default_options();
    options.kinematics = kinematics;
    return options;
}

// Check one element's shape for a formulation (`coords`: x0 y0 x1 y1 ..., counter-clockwise).
inline Status element_check(HyconElementKind kind, View<double> coords) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    return Status::from(hycon_element_check(kind, coords.size() / 2, coords.data()));
}

// Element stiffness matrix, (2n)^2 values row-major (n = coords.size() / 2 nodes).
inline Result<std::vector<double>> element_stiffness(HyconElementKind kind, View<double> coords,
                                                     const HyconMaterial &material) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    const std::size_t n = coords.size() / 2;
    std::vector<double> k(4 * n * n);
    const Status s = Status::from(
        hycon_element_stiffness(kind, n, coords.data(), &material, k.data(), k.size()));
    if (!s.ok()) return s;
    return k;
}

// Stress at the physical point (px, py) of an element from its nodal displacements `q`
// (2n values): {sx, sy, txy} in plane analyses, {sigma_r, sigma_z, tau_rz, sigma_theta} with a
// HYCON_AXISYMMETRIC material (hycon_element_stress_components tells the count).
inline Result<std::vector<double>> element_stress(HyconElementKind kind, View<double> coords,
                                                  const HyconMaterial &material,
                                                  View<double> q, double px, double py) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    if (q.size() != coords.size()) return detail::invalid("q must hold 2 values per node");
    std::size_t count = 0;
    Status s = Status::from(hycon_element_stress_components(&material, &count));
    if (!s.ok()) return s;
    std::vector<double> out(count);
    s = Status::from(hycon_element_stress(kind, coords.size() / 2, coords.data(), &material,
                                          q.data(), px, py, out.data()));
    if (!s.ok()) return s;
    return out;
}

// Stress parameters beta of a hybrid element from its nodal displacements `q` (2n values): 7
// for the 4- and 5-node hybrid element (and the axisymmetric one), 12 with 6 nodes, 5 for
// Pian-Sumihara, none for Q4.
inline Result<std::vector<double>> element_stress_params(HyconElementKind kind,
                                                         View<double> coords,
                                                         const HyconMaterial &material,
                                                         View<double> q) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    if (q.size() != coords.size()) return detail::invalid("q must hold 2 values per node");
    std::vector<double> beta(HYCON_MAX_BETA);
    std::size_t needed = 0;
    const Status s = Status::from(hycon_element_stress_params(kind, coords.size() / 2,
                                                              coords.data(), &material, q.data(),
                                                              beta.data(), beta.size(), &needed));
    if (!s.ok()) return s;
    beta.resize(needed);
    return Result<std::vector<double>>(s, std::move(beta));
}

// Traction {tx, ty} = sigma n (outward n) at parameter s in [0, 1] along edge `edge` (local
// node edge to edge + 1, cyclically) from the nodal displacements `q`; in axisymmetry the
// meridian traction {t_r, t_z}, a pressure.
inline Result<std::array<double, 2>> element_edge_traction(HyconElementKind kind,
                                                           View<double> coords,
                                                           const HyconMaterial &material,
                                                           View<double> q, std::size_t edge,
                                                           double s) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    if (q.size() != coords.size()) return detail::invalid("q must hold 2 values per node");
    std::array<double, 2> out{};
    const Status st = Status::from(hycon_element_edge_traction(
        kind, coords.size() / 2, coords.data(), &material, q.data(), edge, s, out.data()));
    if (!st.ok()) return st;
    return out;
}

// ---------------------------------------------------------------------------------------------
// 3D element routines: 8-node bricks (numbering at HyconBrickKind in hycon.h)

// The brick routines below check the shape under the default policy
// (HYCON_SHAPE_INTEGRATION_POINTS): a brick the strict policy rejects comes back ok() with the
// value and the code HYCON_WARNING_SHAPE, its message naming the corner or the face.

// Check one brick's shape (`coords`: 24 values x0 y0 z0 x1 ...).
inline Status brick_check(HyconBrickKind kind, const std::array<double, 24> &coords) {
    return Status::from(hycon_brick_check(kind, coords.data()));
}

// Check one brick's shape under `policy` (HYCON_SHAPE_INTEGRATION_POINTS or HYCON_SHAPE_STRICT)
// and measure it: the report on success and with a warning (HYCON_WARNING_SHAPE).
inline Result<HyconShapeReport> brick_shape(HyconBrickKind kind,
                                            const std::array<double, 24> &coords,
                                            HyconShapePolicy policy) {
    HyconShapeReport report{};
    const Status s = Status::from(hycon_brick_shape(kind, coords.data(), policy, &report));
    if (!s.ok()) return s;
    return Result<HyconShapeReport>(s, report);
}

// Brick stiffness, 24 x 24 row-major.
inline Result<std::array<double, 576>> brick_stiffness(HyconBrickKind kind,
                                                       const std::array<double, 24> &coords,
                                                       const HyconSolidMaterial &material) {
    std::array<double, 576> k{};
    const Status s =
        Status::from(hycon_brick_stiffness(kind, coords.data(), &material, k.data(), k.size()));
    if (!s.ok()) return s;
    return Result<std::array<double, 576>>(s, k);
}

// Stress parameters beta from the 24 nodal displacements q (18 for the hybrid brick, 0 for H8).
inline Result<std::vector<double>> brick_stress_params(HyconBrickKind kind,
                                                       const std::array<double, 24> &coords,
                                                       const HyconSolidMaterial &material,
                                                       const std::array<double, 24> &q) {
    std::vector<double> beta(HYCON_BRICK_MAX_BETA);
    std::size_t needed = 0;
    const Status s = Status::from(hycon_brick_stress_params(
        kind, coords.data(), &material, q.data(), beta.data(), beta.size(), &needed));
    if (!s.ok()) return s;
    beta.resize(needed);
    return Result<std::vector<double>>(s, std::move(beta));
}

// Stress {sxx, syy, szz, sxy, syz, szx} at the physical point p.
inline Result<std::array<double, 6>> brick_stress(HyconBrickKind kind,
                                                  const std::array<double, 24> &coords,
                                                  const HyconSolidMaterial &material,
                                                  const std::array<double, 24> &q,
                                                  const std::array<double, 3> &p) {
    std::array<double, 6> out{};
    const Status s = Status::from(hycon_brick_stress(kind, coords.data(), &material, q.data(),
                                                     p[0], p[1], p[2], out.data()));
    if (!s.ok()) return s;
    return Result<std::array<double, 6>>(s, out);
}

// Traction sigma n at face parameters (s, t) in [-1, 1]^2 of face `face` (0 to 5).
inline Result<std::array<double, 3>> brick_face_traction(HyconBrickKind kind,
                                                         const std::array<double, 24> &coords,
                                                         const HyconSolidMaterial &material,
                                                         const std::array<double, 24> &q,
                                                         std::size_t face, double s, double t) {
    std::array<double, 3> out{};
    const Status st = Status::from(hycon_brick_face_traction(
        kind, coords.data(), &material, q.data(), face, s, t, out.data()));
    if (!st.ok()) return st;
    return Result<std::array<double, 3>>(st, out);
}

// ---------------------------------------------------------------------------------------------
// Load and check routines (plane, axisymmetric, brick)

// Consistent nodal forces of a load on edge `edge` (local node edge to edge + 1, cyclically):
// `pressure` empty or 2 values (at the edge's two nodes, positive pushing into the body),
// `traction` empty or 4 values {tx0, ty0, tx1, ty1}. The element force vector, 2n values in dof
// order (nonzero at the edge's nodes only; full-circle forces in axisymmetry).
inline Result<std::vector<double>> element_edge_load(HyconElementKind kind, View<double> coords,
                                                     const HyconMaterial &material,
                                                     std::size_t edge, View<double> pressure,
                                                     View<double> traction) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    if (!pressure.empty() && pressure.size() != 2)
        return detail::invalid("pressure must be empty or hold 2 values");
    if (!traction.empty() && traction.size() != 4)
        return detail::invalid("traction must be empty or hold 4 values");
    std::vector<double> f(coords.size());
    const Status s = Status::from(hycon_element_edge_load(kind, coords.size() / 2, coords.data(),
                                                          &material, edge, pressure.data(),
                                                          traction.data(), f.data(), f.size()));
    if (!s.ok()) return s;
    return f;
}

// Volume of an element: A t, or 2 pi r_c A in axisymmetry.
inline Result<double> element_volume(HyconElementKind kind, View<double> coords,
                                     const HyconMaterial &material) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    double v = 0.0;
    const Status s = Status::from(
        hycon_element_volume(kind, coords.size() / 2, coords.data(), &material, &v));
    if (!s.ok()) return s;
    return v;
}

// Scaled Jacobian of an element (smallest sine of a corner angle), in (0, 1].
inline Result<double> element_quality(HyconElementKind kind, View<double> coords) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    double q = 0.0;
    const Status s =
        Status::from(hycon_element_quality(kind, coords.size() / 2, coords.data(), &q));
    if (!s.ok()) return s;
    return q;
}

// Stress at natural coordinates (xi, eta) in [-1, 1]^2 from the nodal displacements `q`: 3
// values, 4 in axisymmetry.
inline Result<std::vector<double>> element_stress_natural(HyconElementKind kind,
                                                          View<double> coords,
                                                          const HyconMaterial &material,
                                                          View<double> q, double xi, double eta) {
    if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
    if (q.size() != coords.size()) return detail::invalid("q must hold 2 values per node");
    std::size_t count = 0;
    Status s = Status::from(hycon_element_stress_components(&material, &count));
    if (!s.ok()) return s;
    std::vector<double> out(count);
    s = Status::from(hycon_element_stress_natural(kind, coords.size() / 2, coords.data(),
                                                  &material, q.data(), xi, eta, out.data()));
    if (!s.ok()) return s;
    return out;
}

// Consistent nodal forces of a load on brick face `face` (0 to 5): `pressure` empty or 4 values
// at the face's nodes (face order), `traction` empty or 12 values {tx, ty, tz} per face node.
inline Result<std::array<double, 24>> brick_face_load(HyconBrickKind kind,
                                                      const std::array<double, 24> &coords,
                                                      std::size_t face, View<double> pressure,
                                                      View<double> traction) {
    if (!pressure.empty() && pressure.size() != 4)
        return detail::invalid("pressure must be empty or hold 4 values");
    if (!traction.empty() && traction.size() != 12)
        return detail::invalid("traction must be empty or hold 12 values");
    std::array<double, 24> f{};
    const Status s = Status::from(hycon_brick_face_load(
        kind, coords.data(), face, pressure.data(), traction.data(), f.data(), f.size()));
    if (!s.ok()) return s;
    return f;
}

// Volume of a brick.
inline Result<double> brick_volume(HyconBrickKind kind, const std::array<double, 24> &coords) {
    double v = 0.0;
    const Status s = Status::from(hycon_brick_volume(kind, coords.data(), &v));
    if (!s.ok()) return s;
    return v;
}

// Scaled Jacobian of a brick (smallest over the corners), in (0, 1].
inline Result<double> brick_quality(HyconBrickKind kind, const std::array<double, 24> &coords) {
    double q = 0.0;
    const Status s = Status::from(hycon_brick_quality(kind, coords.data(), &q));
    if (!s.ok()) return s;
    return q;
}

// Stress {sxx, syy, szz, sxy, syz, szx} at natural coordinates xi in [-1, 1]^3.
inline Result<std::array<double, 6>> brick_stress_natural(HyconBrickKind kind,
                                                          const std::array<double, 24> &coords,
                                                          const HyconSolidMaterial &material,
                                                          const std::array<double, 24> &q,
                                                          const std::array<double, 3> &xi) {
    std::array<double, 6> out{};
    const Status s = Status::from(hycon_brick_stress_natural(
        kind, coords.data(), &material, q.data(), xi[0], xi[1], xi[2], out.data()));
    if (!s.ok()) return s;
    return out;
}

// ---------------------------------------------------------------------------------------------
// Callback adapters

namespace detail {

// Calls `f(args...)`: a callable returning bool reports success with true, one returning void
// always succeeds. Returns the C convention: 0 to go on / success, 1 otherwise.
template <class F, class... Args>
std::int32_t invoke_c(F &f, Args &&...args) noexcept {
    using R = std::invoke_result_t<F &, Args...>;
    static_assert(std::is_void_v<R> || std::is_same_v<R, bool>,
                  "a hycon callback returns bool (true: go on / success) or void");
#if defined(__cpp_exceptions)
    try {
#endif
        if constexpr (std::is_void_v<R>) {
            f(std::forward<Args>(args)...);
            return 0;
        } else {
            return f(std::forward<Args>(args)...) ? 0 : 1;
        }
#if defined(__cpp_exceptions)
    } catch (...) {
        return 1;  // never unwind into hycon: it reports HYCON_ERROR_CALLBACK
    }
#endif
}

template <class F>
std::int32_t monitor_trampoline(void *data, const HyconIterationRecord *record) noexcept {
    if (data == nullptr || record == nullptr) return 1;
    return invoke_c(*static_cast<F *>(data), *record);
}

template <class F>
std::int32_t solve_trampoline(void *data, std::size_t n, std::size_t nrhs, const double *rhs,
                              double *x) noexcept {
    if (data == nullptr) return 1;
    return invoke_c(*static_cast<F *>(data), n, nrhs, rhs, x);
}

template <class F>
void *erase(F &f) noexcept {
    static_assert(std::is_object_v<F>, "pass a callable object (lambda, functor), not a function");
    return const_cast<void *>(static_cast<const void *>(std::addressof(f)));
}

}  // namespace detail

// Make `monitor` the options' iteration monitor: it is called as `monitor(const
// HyconIterationRecord &)` and returns bool (true: go on, false: stop the increment, which then
// fails with HYCON_ERROR_CALLBACK) or void (always go on). Only a pointer to `monitor` is kept:
// it must outlive every Contact created with these options.
template <class F>
void set_monitor(HyconContactOptions &options, F &monitor) noexcept {
    options.monitor = &detail::monitor_trampoline<F>;
    options.monitor_data = detail::erase(monitor);
}
// A temporary would be destroyed before the Contact calls it.
template <class F>
void set_monitor(HyconContactOptions &, const F &&) = delete;

// ---------------------------------------------------------------------------------------------
// Handles

struct ModelDeleter {
    void operator()(HyconModel *p) const noexcept { hycon_model_free(p); }
};
struct HostDeleter {
    void operator()(HyconHost *p) const noexcept { hycon_host_free(p); }
};
struct ContactDeleter {
    void operator()(HyconContact *p) const noexcept { hycon_contact_free(p); }
};
using ModelPtr = std::unique_ptr<HyconModel, ModelDeleter>;
using HostPtr = std::unique_ptr<HyconHost, HostDeleter>;
using ContactPtr = std::unique_ptr<HyconContact, ContactDeleter>;

// A model being described (model API): mesh, materials, prescribed directions, contact pairs,
// optional rigid plate.
class Model {
  public:
    Model() noexcept = default;
    explicit Model(ModelPtr handle) noexcept : handle_(std::move(handle)) {}

    // Nodes `coords` (x0 y0 x1 y1 ...), elements in compressed form (element e has the nodes
    // element_nodes[element_offsets[e] .. element_offsets[e + 1]], counter-clockwise),
    // `materials`, and per element an index into them (`element_materials`; empty: all 0).
    static Result<Model> create(View<double> coords, View<std::size_t> element_offsets,
                                View<std::size_t> element_nodes, View<HyconMaterial> materials,
                                HyconElementKind kind,
                                View<std::size_t> element_materials = {}) {
        if (coords.size() % 2 != 0) return detail::invalid("coords must hold x y pairs");
        if (element_offsets.size() < 2)
            return detail::invalid("element_offsets needs n_elements + 1 >= 2 entries");
        const std::size_t n_elements = element_offsets.size() - 1;
        if (element_nodes.size() != element_offsets.back())
            return detail::invalid("element_nodes must hold element_offsets.back() ids");
        if (!element_materials.empty() && element_materials.size() != n_elements)
            return detail::invalid("element_materials must be empty or hold one index per element");
        const HyconElementBlock elements = {element_offsets.data(), element_nodes.data(),
                                            n_elements,
                                            element_materials.empty() ? nullptr
                                                                      : element_materials.data(),
                                            kind};
        HyconModel *raw = nullptr;
        const Status s = Status::from(hycon_model_new(&raw, coords.data(), coords.size() / 2,
                                                      &elements, materials.data(),
                                                      materials.size()));
        if (!s.ok()) return s;
        return Model(ModelPtr(raw));
    }

    // Prescribe the displacement of `nodes` in `directions` (HYCON_X, HYCON_Y, HYCON_XY).
    Status prescribe(View<std::size_t> nodes, HyconDirections directions) {
        return Status::from(hycon_model_prescribe(get(), nodes.data(), nodes.size(), directions));
    }

    // Add a contact pair (A the multiplier side, each polyline with its body on the left);
    // returns the pair's index.
    Result<std::size_t> add_pair(View<std::size_t> a, View<std::size_t> b, double friction) {
        const HyconPolyline pa = {a.data(), a.size()};
        const HyconPolyline pb = {b.data(), b.size()};
        std::size_t index = 0;
        const Status s = Status::from(hycon_model_add_pair(get(), &pa, &pb, friction, &index));
        return Result<std::size_t>(s, index);
    }

    // Tie `nodes` to a rigid plate driven by Contact::increment_with_plate.
    Status set_plate(View<std::size_t> nodes) {
        return Status::from(hycon_model_set_plate(get(), nodes.data(), nodes.size()));
    }

    HyconModel *get() const noexcept { return handle_.get(); }
    explicit operator bool() const noexcept { return static_cast<bool>(handle_); }
    // Give up ownership (the caller then frees with hycon_model_free).
    HyconModel *release() noexcept { return handle_.release(); }

  private:
    ModelPtr handle_;
};

// A host's contact description (host-assembly API): contact polylines in the host's numbering
// and its stiffness (CSR) or solver.
class Host {
  public:
    Host() noexcept = default;
    Host(HostPtr handle, std::size_t n_equations) noexcept
        : handle_(std::move(handle)), equations_(n_equations) {}

    static Result<Host> create(std::size_t n_equations) {
        HyconHost *raw = nullptr;
        const Status s = Status::from(hycon_host_new(&raw, n_equations));
        if (!s.ok()) return s;
        return Host(HostPtr(raw), n_equations);
    }

    // Add a pair: per polyline, node ids, 2 n reference coordinates and 2 n equation numbers
    // (HYCON_FIXED for a dof held at zero); the A side's analysis kind and thickness (the
    // contact tractions are pressures on A's surface measure; one kind per host, elements
    // along A of the pair's kind and thickness, no axisymmetric node at r < 0: see
    // hycon_host_add_pair). Returns the pair's index.
    Result<std::size_t> add_pair(View<std::size_t> a_nodes, View<double> a_coords,
                                 View<std::int64_t> a_equations, View<std::size_t> b_nodes,
                                 View<double> b_coords, View<std::int64_t> b_equations,
                                 double friction, HyconAnalysis analysis, double thickness) {
        if (a_coords.size() != 2 * a_nodes.size() || a_equations.size() != 2 * a_nodes.size() ||
            b_coords.size() != 2 * b_nodes.size() || b_equations.size() != 2 * b_nodes.size())
            return detail::invalid("each polyline needs 2 coordinates and 2 equations per node");
        const HyconHostNodes a = {a_nodes.data(), a_coords.data(), a_equations.data(),
                                  a_nodes.size()};
        const HyconHostNodes b = {b_nodes.data(), b_coords.data(), b_equations.data(),
                                  b_nodes.size()};
        std::size_t index = 0;
        const Status s = Status::from(hycon_host_add_pair(get(), &a, &b, friction, analysis,
                                                          thickness, &index));
        return Result<std::size_t>(s, index);
    }

    // Say which side body A of a pair is on: a point inside it, beside its polyline (needed
    // where A and B touch everywhere, which the geometry alone cannot tell from a pair lying
    // back to back; see hycon_host_set_pair_inside).
    Status set_pair_inside(std::size_t pair, std::array<double, 2> inside) {
        return Status::from(hycon_host_set_pair_inside(get(), pair, inside.data()));
    }

    // The stiffness in CSR over the n_equations equations (copied).
    Status set_csr(View<std::size_t> row_ptr, View<std::size_t> columns, View<double> values,
                   HyconTriangle triangle) {
        if (row_ptr.size() != equations_ + 1)
            return detail::invalid("row_ptr must hold n_equations + 1 entries");
        if (columns.size() < row_ptr.back() || values.size() < row_ptr.back())
            return detail::invalid("columns and values must hold row_ptr[n_equations] entries");
        return Status::from(
            hycon_host_set_csr(get(), row_ptr.data(), columns.data(), values.data(), triangle));
    }

    // The elements of body A along its contact polylines (hycon formulations, counter-clockwise,
    // host node ids), so that Contact::stress_tractions works on this host (not on the
    // condensed path); an element along A has its pair's kind and thickness. The order of
    // hycon_host_set_elements (and of Model::create): nodes, elements, materials. The node
    // table gives each node's id, coordinates (2 each) and equations (2 each, HYCON_FIXED if
    // held).
    Status set_elements(View<std::size_t> node_ids, View<double> coords,
                        View<std::int64_t> equations, View<std::size_t> element_offsets,
                        View<std::size_t> element_nodes, HyconElementKind kind,
                        View<HyconMaterial> materials,
                        View<std::size_t> element_materials = {}) {
        if (element_offsets.size() < 2)
            return detail::invalid("element_offsets needs n_elements + 1 >= 2 entries");
        const std::size_t n_elements = element_offsets.size() - 1;
        if (element_nodes.size() != element_offsets.back())
            return detail::invalid("element_nodes must hold element_offsets.back() ids");
        if (!element_materials.empty() && element_materials.size() != n_elements)
            return detail::invalid("element_materials must be empty or hold one index per element");
        if (coords.size() != 2 * node_ids.size() || equations.size() != 2 * node_ids.size())
            return detail::invalid("coords and equations must hold 2 values per node id");
        const HyconHostNodes nodes = {node_ids.data(), coords.data(), equations.data(),
                                      node_ids.size()};
        const HyconElementBlock elements = {element_offsets.data(), element_nodes.data(),
                                            n_elements,
                                            element_materials.empty() ? nullptr
                                                                      : element_materials.data(),
                                            kind};
        return Status::from(
            hycon_host_set_elements(get(), &nodes, &elements, materials.data(), materials.size()));
    }

    // The host's own solver: `solve(std::size_t n, std::size_t nrhs, const double *rhs,
    // double *x)` solves K x_j = rhs_j for nrhs column-major right-hand sides and returns bool
    // (true: success) or void. Only a pointer to `solve` is kept: it must outlive this Host and
    // every Contact created from it.
    template <class F>
    Status set_solver(F &solve) {
        return set_solver(&detail::solve_trampoline<F>, detail::erase(solve));
    }
    template <class F>
    Status set_solver(const F &&) = delete;  // a temporary would dangle
    // The C form: a HyconSolveFn and its user data.
    Status set_solver(HyconSolveFn solve, void *user_data) {
        return Status::from(hycon_host_set_solver(get(), solve, user_data));
    }

    // The host's condensed operator over its candidate equations (copied): the stiffness
    // Schur complement (HYCON_CONDENSED_STIFFNESS) or the flexibility block
    // (HYCON_CONDENSED_FLEXIBILITY), m x m column-major in the order of `equations`. Increments
    // then take the load image u0 = K^-1 rhs at the candidates; the host recovers its
    // displacement with Contact::forces (see hycon_host_set_condensed): Contact::displacement
    // and Contact::stress_tractions fail on this path.
    Status set_condensed(HyconCondensedKind kind, View<std::int64_t> equations,
                         View<double> matrix) {
        if (matrix.size() != equations.size() * equations.size())
            return detail::invalid("the condensed matrix must hold m * m values");
        HyconCondensed c = {};
        c.size = sizeof(HyconCondensed);
        c.kind = kind;
        c.m = equations.size();
        c.equations = equations.data();
        c.matrix = matrix.data();
        return Status::from(hycon_host_set_condensed(get(), &c));
    }

    // The equations of the contact nodes, in the order they were first given (u_x, u_y):
    // what the candidates of set_condensed must hold.
    Result<std::vector<std::int64_t>> contact_equations() const {
        std::size_t n = 0;
        Status s = Status::from(hycon_host_contact_equations(get(), nullptr, 0, &n));
        if (!s.ok()) return s;
        std::vector<std::int64_t> out(n);
        if (n == 0) return out;
        s = Status::from(hycon_host_contact_equations(get(), out.data(), n, nullptr));
        if (!s.ok()) return s;
        return out;
    }

    std::size_t equations() const noexcept { return equations_; }
    HyconHost *get() const noexcept { return handle_.get(); }
    explicit operator bool() const noexcept { return static_cast<bool>(handle_); }
    HyconHost *release() noexcept { return handle_.release(); }

  private:
    HostPtr handle_;
    std::size_t equations_ = 0;
};

// How one plate translation is driven in an increment.
struct PlateDrive {
    HyconPlateControl control;
    double value;
};
// The plate's total displacement in that direction.
inline PlateDrive plate_displacement(double value) noexcept {
    return {HYCON_PLATE_DISPLACEMENT, value};
}
// The total force on the plate in that direction (its motion is solved for).
inline PlateDrive plate_force(double value) noexcept { return {HYCON_PLATE_FORCE, value}; }

// The converged plate state: displacement and the force it exerts on the body (x, y).
struct PlateState {
    std::array<double, 2> displacement{};
    std::array<double, 2> force{};
};

// The converged plate state of a 3D model: displacement and the force it exerts on the body
// (x, y, z).
struct SolidPlateState {
    std::array<double, 3> displacement{};
    std::array<double, 3> force{};
};

// Sizes of a pair's polylines.
struct PairSize {
    std::size_t a = 0;
    std::size_t b = 0;
};

// Timings and the number of factorizations done by hycon.
struct Timings {
    HyconTimings seconds{};
    std::size_t factorizations = 0;
};

namespace detail {

// The size convention: ask for the size with (NULL, 0, &n), then fill n elements.
template <class T, class Fill>
Result<std::vector<T>> fetch(Fill fill) {
    std::size_t n = 0;
    Status s = Status::from(fill(nullptr, 0, &n));
    if (!s.ok()) return s;
    std::vector<T> out(n);
    if (n == 0) return out;
    s = Status::from(fill(out.data(), out.size(), nullptr));
    if (!s.ok()) return s;
    return out;
}

// The C functions whose meaning does not depend on the dimension, overloaded on the handle
// type: the plane's hycon_contact_* and the solid's hycon_solid_contact_*.
#define HYCON_DETAIL_BOTH(name, plane, solid)                                                   \
    template <class... Args>                                                                    \
    HyconStatus name(const HyconContact *c, Args... args) {                                     \
        return plane(c, args...);                                                               \
    }                                                                                           \
    template <class... Args>                                                                    \
    HyconStatus name(const HyconSolidContact *c, Args... args) {                                \
        return solid(c, args...);                                                               \
    }
HYCON_DETAIL_BOTH(displacement, hycon_contact_displacement, hycon_solid_contact_displacement)
HYCON_DETAIL_BOTH(displacement_increment, hycon_contact_displacement_increment,
                  hycon_solid_contact_displacement_increment)
HYCON_DETAIL_BOTH(forces, hycon_contact_forces, hycon_solid_contact_forces)
HYCON_DETAIL_BOTH(records, hycon_contact_records, hycon_solid_contact_records)
HYCON_DETAIL_BOTH(timings, hycon_contact_timings, hycon_solid_contact_timings)
HYCON_DETAIL_BOTH(surface_coupling, hycon_contact_surface_coupling,
                  hycon_solid_contact_surface_coupling)
HYCON_DETAIL_BOTH(constraint_rows, hycon_contact_constraint_rows,
                  hycon_solid_contact_constraint_rows)
#undef HYCON_DETAIL_BOTH
inline HyconStatus increment(HyconContact *c, const double *load, std::size_t load_len,
                             const double *prescribed, std::size_t prescribed_len,
                             HyconIncrementInfo *info) {
    return hycon_contact_increment(c, load, load_len, prescribed, prescribed_len, info);
}
inline HyconStatus increment(HyconSolidContact *c, const double *load, std::size_t load_len,
                             const double *prescribed, std::size_t prescribed_len,
                             HyconIncrementInfo *info) {
    return hycon_solid_contact_increment(c, load, load_len, prescribed, prescribed_len, info);
}

// The members of Contact and SolidContact whose meaning does not depend on the dimension,
// written once over the handle `H` owned by `Ptr`.
template <class H, class Ptr>
class Analysis {
  public:
    Analysis() noexcept = default;
    explicit Analysis(Ptr handle) noexcept : handle_(std::move(handle)) {}

    // Length of the load and displacement vectors (the size query of the displacement).
    Result<std::size_t> field_len() const {
        std::size_t n = 0;
        const Status s = Status::from(detail::displacement(get(), nullptr, 0, &n));
        return Result<std::size_t>(s, n);
    }

    // One increment with total values (see hycon_contact_increment).
    Result<HyconIncrementInfo> increment(View<double> load, View<double> prescribed = {}) {
        HyconIncrementInfo info{};
        const Status s = Status::from(detail::increment(get(), load.data(), load.size(),
                                                        prescribed.data(), prescribed.size(),
                                                        &info));
        return Result<HyconIncrementInfo>(s, info);
    }

    // Total displacement of the last converged increment over the field.
    Result<std::vector<double>> displacement() const {
        return fetch<double>([this](double *out, std::size_t n, std::size_t *needed) {
            return detail::displacement(get(), out, n, needed);
        });
    }

    // The last converged increment's displacement minus the previous one's (one solve).
    Result<std::vector<double>> displacement_increment() const {
        return fetch<double>([this](double *out, std::size_t n, std::size_t *needed) {
            return detail::displacement_increment(get(), out, n, needed);
        });
    }

    // Contact forces of the last converged increment over the field.
    Result<std::vector<double>> forces() const {
        return fetch<double>([this](double *out, std::size_t n, std::size_t *needed) {
            return detail::forces(get(), out, n, needed);
        });
    }

    // The iteration records from `first` on (all increments, failed ones excluded).
    Result<std::vector<HyconIterationRecord>> records(std::size_t first = 0) const {
        return fetch<HyconIterationRecord>(
            [this, first](HyconIterationRecord *out, std::size_t n, std::size_t *needed) {
                return detail::records(get(), first, out, n, needed);
            });
    }

    Result<Timings> timings() const {
        Timings t;
        const Status s = Status::from(detail::timings(get(), &t.seconds, &t.factorizations));
        return Result<Timings>(s, t);
    }

    // The entries of F^A and F^B of `pair`.
    Result<std::vector<HyconCouplingEntry>> surface_coupling(std::size_t pair) const {
        return fetch<HyconCouplingEntry>(
            [this, pair](HyconCouplingEntry *out, std::size_t n, std::size_t *needed) {
                return detail::surface_coupling(get(), pair, out, n, needed);
            });
    }

    // The constraint matrix Kc of `pair` (2 n_a rows in the plane, 3 n_a in 3D) as row-major
    // entries (CSR-ready).
    Result<std::vector<HyconConstraintEntry>> constraint_rows(std::size_t pair) const {
        return fetch<HyconConstraintEntry>(
            [this, pair](HyconConstraintEntry *out, std::size_t n, std::size_t *needed) {
                return detail::constraint_rows(get(), pair, out, n, needed);
            });
    }

    H *get() const noexcept { return handle_.get(); }
    explicit operator bool() const noexcept { return static_cast<bool>(handle_); }
    H *release() noexcept { return handle_.release(); }

  private:
    Ptr handle_;
};

}  // namespace detail

// A contact analysis: K factored once, the converged state, the records.
class Contact : public detail::Analysis<HyconContact, ContactPtr> {
  public:
    Contact() noexcept = default;
    explicit Contact(ContactPtr handle) noexcept : Analysis(std::move(handle)) {}

    // Model API. The model is copied (it may be destroyed or changed afterwards).
    static Result<Contact> create(const Model &model,
                                  const HyconContactOptions &options = default_options()) {
        HyconContact *raw = nullptr;
        const Status s = Status::from(hycon_contact_new(&raw, model.get(), &options));
        if (!s.ok()) return s;
        return Contact(ContactPtr(raw));
    }
    // Host-assembly API. The host description is copied, its solver's callable is not.
    static Result<Contact> create(const Host &host,
                                  const HyconContactOptions &options = default_options()) {
        HyconContact *raw = nullptr;
        const Status s = Status::from(hycon_contact_new_host(&raw, host.get(), &options));
        if (!s.ok()) return s;
        return Contact(ContactPtr(raw));
    }

    // One increment of a model with a plate, its x and y translations driven by `x` and `y`.
    Result<HyconIncrementInfo> increment_with_plate(View<double> load, View<double> prescribed,
                                                    PlateDrive x, PlateDrive y) {
        const HyconPlateControl control[2] = {x.control, y.control};
        const double value[2] = {x.value, y.value};
        HyconIncrementInfo info{};
        const Status s = Status::from(
            hycon_contact_increment_with_plate(get(), load.data(), load.size(), prescribed.data(),
                                               prescribed.size(), control, value, &info));
        return Result<HyconIncrementInfo>(s, info);
    }

    Result<PlateState> plate() const {
        PlateState p;
        const Status s =
            Status::from(hycon_contact_plate(get(), p.displacement.data(), p.force.data()));
        return Result<PlateState>(s, p);
    }

    // Node counts of the A and B polylines of `pair` (the size queries of the node results).
    Result<PairSize> pair_size(std::size_t pair) const {
        PairSize size;
        Status s = Status::from(hycon_contact_node_results(get(), pair, nullptr, 0, &size.a));
        if (s.ok())
            s = Status::from(hycon_contact_b_node_results(get(), pair, nullptr, 0, &size.b));
        return Result<PairSize>(s, size);
    }

    // The multipliers and states at the A nodes of `pair`.
    Result<std::vector<HyconNodeResult>> node_results(std::size_t pair) const {
        return detail::fetch<HyconNodeResult>(
            [this, pair](HyconNodeResult *out, std::size_t n, std::size_t *needed) {
                return hycon_contact_node_results(get(), pair, out, n, needed);
            });
    }

    // Forces, weights and pressures at the B nodes of `pair`.
    Result<std::vector<HyconBNodeResult>> b_node_results(std::size_t pair) const {
        return detail::fetch<HyconBNodeResult>(
            [this, pair](HyconBNodeResult *out, std::size_t n, std::size_t *needed) {
                return hycon_contact_b_node_results(get(), pair, out, n, needed);
            });
    }

    // tn ts per A node of `pair` from body A's element stresses, 2 n_a values (a host: with
    // its elements handed over, not on the condensed path).
    Result<std::vector<double>> stress_tractions(std::size_t pair) const {
        return detail::fetch<double>([this, pair](double *out, std::size_t n, std::size_t *needed) {
            return hycon_contact_stress_tractions(get(), pair, out, n, needed);
        });
    }

    // Contact-element quantities of the A nodes of `pair`.
    Result<std::vector<HyconContactNode>> surface_nodes(std::size_t pair) const {
        return detail::fetch<HyconContactNode>(
            [this, pair](HyconContactNode *out, std::size_t n, std::size_t *needed) {
                return hycon_contact_surface_nodes(get(), pair, out, n, needed);
            });
    }
};

// ---------------------------------------------------------------------------------------------
// 3D contact, model family: a brick model with contact pairs of brick faces

struct SolidModelDeleter {
    void operator()(HyconSolidModel *p) const noexcept { hycon_solid_model_free(p); }
};
struct SolidContactDeleter {
    void operator()(HyconSolidContact *p) const noexcept { hycon_solid_contact_free(p); }
};
using SolidModelPtr = std::unique_ptr<HyconSolidModel, SolidModelDeleter>;
using SolidContactPtr = std::unique_ptr<HyconSolidContact, SolidContactDeleter>;

// A brick face of a surface: the brick's index and its local face (0-5, outward).
struct BrickFace {
    std::size_t brick;
    std::size_t face;
};

// A 3D model being described: brick mesh, materials, prescribed directions, contact pairs of
// brick faces, symmetry planes.
class SolidModel {
  public:
    SolidModel() noexcept = default;
    explicit SolidModel(SolidModelPtr handle) noexcept : handle_(std::move(handle)) {}

    // Nodes `coords` (x0 y0 z0 x1 ...), bricks `brick_nodes` (8 ids each, brick node order),
    // `materials`, and per brick an index into them (`brick_materials`; empty: all 0). A brick
    // the default shape policy warns about gives an ok() result with HYCON_WARNING_SHAPE.
    static Result<SolidModel> create(View<double> coords, View<std::size_t> brick_nodes,
                                     View<HyconSolidMaterial> materials, HyconBrickKind kind,
                                     View<std::size_t> brick_materials = {}) {
        if (coords.size() % 3 != 0) return detail::invalid("coords must hold x y z triples");
        if (brick_nodes.size() % 8 != 0)
            return detail::invalid("brick_nodes must hold 8 node ids per brick");
        const std::size_t n_bricks = brick_nodes.size() / 8;
        if (!brick_materials.empty() && brick_materials.size() != n_bricks)
            return detail::invalid("brick_materials must be empty or hold one index per brick");
        const HyconBrickBlock bricks = {
            brick_nodes.data(), n_bricks,
            brick_materials.empty() ? nullptr : brick_materials.data(), kind};
        HyconSolidModel *raw = nullptr;
        const Status s = Status::from(hycon_solid_model_new(
            &raw, coords.data(), coords.size() / 3, &bricks, materials.data(), materials.size()));
        if (!s.ok()) return s;
        return Result<SolidModel>(s, SolidModel(SolidModelPtr(raw)));
    }

    // Prescribe the displacement of `nodes` in `directions` (an OR of HYCON_X, HYCON_Y, HYCON_Z).
    Status prescribe(View<std::size_t> nodes, HyconDirections directions) {
        return Status::from(
            hycon_solid_model_prescribe(get(), nodes.data(), nodes.size(), directions));
    }

    // Add a contact pair of brick faces (A the multiplier side); returns the pair's index.
    Result<std::size_t> add_pair(View<BrickFace> a, View<BrickFace> b, double friction) {
        const std::vector<std::size_t> fa = flatten(a), fb = flatten(b);
        const HyconBrickFaces va = {fa.empty() ? nullptr : fa.data(), a.size()};
        const HyconBrickFaces vb = {fb.empty() ? nullptr : fb.data(), b.size()};
        std::size_t index = 0;
        const Status s =
            Status::from(hycon_solid_model_add_pair(get(), &va, &vb, friction, &index));
        return Result<std::size_t>(s, index);
    }

    // Declare the symmetry plane through `point` normal to `normal`.
    Status add_symmetry_plane(const std::array<double, 3> &point,
                              const std::array<double, 3> &normal) {
        return Status::from(
            hycon_solid_model_add_symmetry_plane(get(), point.data(), normal.data()));
    }

    // Tie `nodes` to a rigid plate driven by SolidContact::increment_with_plate.
    Status set_plate(View<std::size_t> nodes) {
        return Status::from(hycon_solid_model_set_plate(get(), nodes.data(), nodes.size()));
    }

    HyconSolidModel *get() const noexcept { return handle_.get(); }
    explicit operator bool() const noexcept { return static_cast<bool>(handle_); }
    // Give up ownership (the caller then frees with hycon_solid_model_free).
    HyconSolidModel *release() noexcept { return handle_.release(); }

  private:
    static std::vector<std::size_t> flatten(View<BrickFace> faces) {
        std::vector<std::size_t> flat;
        flat.reserve(2 * faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i) {
            flat.push_back(faces[i].brick);
            flat.push_back(faces[i].face);
        }
        return flat;
    }

    SolidModelPtr handle_;
};

// A 3D host's contact description (host API): contact nodes with 3 equations each, pairs of
// faces given as 4 node ids of the host's numbering, symmetry planes, and its stiffness (CSR),
// solver or condensed operator. SolidContact::create(const SolidHost &) starts the analysis.
struct SolidHostDeleter {
    void operator()(HyconSolidHost *p) const noexcept { hycon_solid_host_free(p); }
};
using SolidHostPtr = std::unique_ptr<HyconSolidHost, SolidHostDeleter>;

class SolidHost {
  public:
    SolidHost() noexcept = default;
    SolidHost(SolidHostPtr handle, std::size_t n_equations) noexcept
        : handle_(std::move(handle)), equations_(n_equations) {}

    static Result<SolidHost> create(std::size_t n_equations) {
        HyconSolidHost *raw = nullptr;
        const Status s = Status::from(hycon_solid_host_new(&raw, n_equations));
        if (!s.ok()) return s;
        return SolidHost(SolidHostPtr(raw), n_equations);
    }

    // Add contact nodes: ids, 3 n reference coordinates, 3 n equations (HYCON_FIXED for a dof
    // held at zero). Every node of a face must be added before its pair; their order is the
    // order of the per-node results.
    Status add_nodes(View<std::size_t> ids, View<double> coords, View<std::int64_t> equations) {
        if (coords.size() != 3 * ids.size() || equations.size() != 3 * ids.size())
            return detail::invalid("nodes need 3 coordinates and 3 equations each");
        const HyconSolidHostNodes nodes = {ids.data(), coords.data(), equations.data(),
                                           ids.size()};
        return Status::from(hycon_solid_host_add_nodes(get(), &nodes));
    }

    // Add a pair of faces, 4 node ids each (counter-clockwise seen from outside their body;
    // A the multiplier side); returns the pair's index.
    Result<std::size_t> add_pair(View<std::size_t> a_faces, View<std::size_t> b_faces,
                                 double friction) {
        if (a_faces.size() % 4 != 0 || b_faces.size() % 4 != 0)
            return detail::invalid("faces need 4 node ids each");
        const HyconHostFaces a = {a_faces.data(), a_faces.size() / 4};
        const HyconHostFaces b = {b_faces.data(), b_faces.size() / 4};
        std::size_t index = 0;
        const Status s =
            Status::from(hycon_solid_host_add_pair(get(), &a, &b, friction, &index));
        return Result<std::size_t>(s, index);
    }

    // A point inside body A of `pair` (needed where A and B touch everywhere; see
    // hycon_solid_host_set_pair_inside).
    Status set_pair_inside(std::size_t pair, const std::array<double, 3> &inside) {
        return Status::from(hycon_solid_host_set_pair_inside(get(), pair, inside.data()));
    }

    // Declare the symmetry plane through `point` normal to `normal`.
    Status add_symmetry_plane(const std::array<double, 3> &point,
                              const std::array<double, 3> &normal) {
        return Status::from(
            hycon_solid_host_add_symmetry_plane(get(), point.data(), normal.data()));
    }

    // The stiffness in CSR over the n_equations equations (copied), as Host::set_csr.
    Status set_csr(View<std::size_t> row_ptr, View<std::size_t> columns, View<double> values,
                   HyconTriangle triangle) {
        if (row_ptr.size() != equations_ + 1)
            return detail::invalid("row_ptr must hold n_equations + 1 entries");
        if (columns.size() < row_ptr.back() || values.size() < row_ptr.back())
            return detail::invalid("columns and values must hold row_ptr[n_equations] entries");
        return Status::from(hycon_solid_host_set_csr(get(), row_ptr.data(), columns.data(),
                                                     values.data(), triangle));
    }

    // The host's own solver, as Host::set_solver (only a pointer to `solve` is kept).
    template <class F>
    Status set_solver(F &solve) {
        return set_solver(&detail::solve_trampoline<F>, detail::erase(solve));
    }
    template <class F>
    Status set_solver(const F &&) = delete;  // a temporary would dangle
    Status set_solver(HyconSolveFn solve, void *user_data) {
        return Status::from(hycon_solid_host_set_solver(get(), solve, user_data));
    }

    // The condensed operator over the candidate equations, as Host::set_condensed.
    Status set_condensed(HyconCondensedKind kind, View<std::int64_t> equations,
                         View<double> matrix) {
        if (matrix.size() != equations.size() * equations.size())
            return detail::invalid("the condensed matrix must hold m * m values");
        HyconCondensed c = {};
        c.size = sizeof(HyconCondensed);
        c.kind = kind;
        c.m = equations.size();
        c.equations = equations.data();
        c.matrix = matrix.data();
        return Status::from(hycon_solid_host_set_condensed(get(), &c));
    }

    // The equations of the contact nodes in the order they were added (u_x, u_y, u_z).
    Result<std::vector<std::int64_t>> contact_equations() const {
        return detail::fetch<std::int64_t>(
            [this](std::int64_t *out, std::size_t n, std::size_t *needed) {
                return hycon_solid_host_contact_equations(get(), out, n, needed);
            });
    }

    std::size_t equations() const noexcept { return equations_; }
    HyconSolidHost *get() const noexcept { return handle_.get(); }
    explicit operator bool() const noexcept { return static_cast<bool>(handle_); }
    HyconSolidHost *release() noexcept { return handle_.release(); }

  private:
    SolidHostPtr handle_;
    std::size_t equations_ = 0;
};

// A 3D contact analysis: K factored once, the converged state, the records.
class SolidContact : public detail::Analysis<HyconSolidContact, SolidContactPtr> {
  public:
    SolidContact() noexcept = default;
    explicit SolidContact(SolidContactPtr handle) noexcept : Analysis(std::move(handle)) {}

    // The model is copied (it may be destroyed or changed afterwards).
    static Result<SolidContact> create(const SolidModel &model,
                                       const HyconContactOptions &options = default_options()) {
        HyconSolidContact *raw = nullptr;
        const Status s = Status::from(hycon_solid_contact_new(&raw, model.get(), &options));
        if (!s.ok()) return s;
        return SolidContact(SolidContactPtr(raw));
    }
    // Host API: loads over the host's equations (prescribed empty). The host description is
    // copied, its solver's callable is not.
    static Result<SolidContact> create(const SolidHost &host,
                                       const HyconContactOptions &options = default_options()) {
        HyconSolidContact *raw = nullptr;
        const Status s = Status::from(hycon_solid_contact_new_host(&raw, host.get(), &options));
        if (!s.ok()) return s;
        return SolidContact(SolidContactPtr(raw));
    }

    // One increment of a model with a plate, its x, y and z translations driven by `x`, `y`
    // and `z`.
    Result<HyconIncrementInfo> increment_with_plate(View<double> load, View<double> prescribed,
                                                    PlateDrive x, PlateDrive y, PlateDrive z) {
        const HyconPlateControl control[3] = {x.control, y.control, z.control};
        const double value[3] = {x.value, y.value, z.value};
        HyconIncrementInfo info{};
        const Status s = Status::from(hycon_solid_contact_increment_with_plate(
            get(), load.data(), load.size(), prescribed.data(), prescribed.size(), control, value,
            &info));
        return Result<HyconIncrementInfo>(s, info);
    }

    Result<SolidPlateState> plate() const {
        SolidPlateState p;
        const Status s = Status::from(
            hycon_solid_contact_plate(get(), p.displacement.data(), p.force.data()));
        return Result<SolidPlateState>(s, p);
    }

    // Node counts of the A and B sides of `pair` (the size queries of the node results).
    Result<PairSize> pair_size(std::size_t pair) const {
        PairSize size;
        Status s =
            Status::from(hycon_solid_contact_node_results(get(), pair, nullptr, 0, &size.a));
        if (s.ok())
            s = Status::from(
                hycon_solid_contact_b_node_results(get(), pair, nullptr, 0, &size.b));
        return Result<PairSize>(s, size);
    }

    // The multipliers, states and slip directions at the A nodes of `pair`.
    Result<std::vector<HyconSolidNodeResult>> node_results(std::size_t pair) const {
        return detail::fetch<HyconSolidNodeResult>(
            [this, pair](HyconSolidNodeResult *out, std::size_t n, std::size_t *needed) {
                return hycon_solid_contact_node_results(get(), pair, out, n, needed);
            });
    }

    // Forces, weights and pressures at the B nodes of `pair`.
    Result<std::vector<HyconSolidBNodeResult>> b_node_results(std::size_t pair) const {
        return detail::fetch<HyconSolidBNodeResult>(
            [this, pair](HyconSolidBNodeResult *out, std::size_t n, std::size_t *needed) {
                return hycon_solid_contact_b_node_results(get(), pair, out, n, needed);
            });
    }

    // Contact-element quantities of the A nodes of `pair`.
    Result<std::vector<HyconSolidContactNode>> surface_nodes(std::size_t pair) const {
        return detail::fetch<HyconSolidContactNode>(
            [this, pair](HyconSolidContactNode *out, std::size_t n, std::size_t *needed) {
                return hycon_solid_contact_surface_nodes(get(), pair, out, n, needed);
            });
    }
};

}  // namespace hycon

#endif  // HYCON_HPP
