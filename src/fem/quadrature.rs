//! Gauss rules on a line, a quadrilateral's bilinear weights, and the triangle rules the plane
//! hybrid element integrates its polygon with.

/// Two-point Gauss rule on `[0, 1]`: `(abscissa, weight)`; exact for cubics.
pub const GAUSS2_UNIT: [(f64, f64); 2] = [
    (0.211_324_865_405_187_1, 0.5),
    (0.788_675_134_594_812_9, 0.5),
];

/// Two-point Gauss rule on `[-1, 1]`: `(abscissa, weight)`; exact for cubics.
pub const GAUSS2: [(f64, f64); 2] = [
    (-0.577_350_269_189_625_8, 1.0),
    (0.577_350_269_189_625_8, 1.0),
];

/// Three-point Gauss rule on `[-1, 1]`: `(abscissa, weight)`; exact for quintics.
pub const GAUSS3: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];

/// Strang and Fix's 3-point rule on a triangle, exact for polynomials of degree 2: barycentric
/// coordinates and weights summing to 1.
pub const STRANG_FIX2: [([f64; 3], f64); 3] = [
    ([2.0 / 3.0, 1.0 / 6.0, 1.0 / 6.0], 1.0 / 3.0),
    ([1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0], 1.0 / 3.0),
    ([1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0], 1.0 / 3.0),
];

/// Dunavant's 6-point rule on a triangle, exact for polynomials of degree 4: barycentric
/// coordinates `(l1, l2, l3)` and weights summing to 1 (multiply by the triangle's area).
pub const DUNAVANT4: [([f64; 3], f64); 6] = {
    const A: f64 = 0.445_948_490_915_965;
    const B: f64 = 0.108_103_018_168_070;
    const C: f64 = 0.091_576_213_509_771;
    const D: f64 = 0.816_847_572_980_459;
    const WA: f64 = 0.223_381_589_678_011;
    const WC: f64 = 0.109_951_743_655_322;
    [
        ([A, A, B], WA),
        ([A, B, A], WA),
        ([B, A, A], WA),
        ([C, C, D], WC),
        ([C, D, C], WC),
        ([D, C, C], WC),
    ]
};

/// Bilinear weights `M_k(s, t)` of a quadrilateral's 4 nodes at `(s, t)` in `[-1, 1]^2`: the
/// first node at `(-1, -1)`, the second at `(1, -1)`, the third at `(1, 1)`, the fourth at
/// `(-1, 1)`.
pub fn quad_weights(s: f64, t: f64) -> [f64; 4] {
    [
        0.25 * (1.0 - s) * (1.0 - t),
        0.25 * (1.0 + s) * (1.0 - t),
        0.25 * (1.0 + s) * (1.0 + t),
        0.25 * (1.0 - s) * (1.0 + t),
    ]
}
