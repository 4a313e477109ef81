#pragma once
// Geometric metrics: sizes that bound the gap between a curve or surface and its piecewise linear
// approximation, from local differential geometry (BOOK.md §1 "Geometric metrics (curves and
// surfaces)"). Inputs are derivatives at one point; nothing here knows about meshes or CAD.
#include "core/mat.hpp"
#include "core/symmat.hpp"
#include "core/vec.hpp"

namespace riemesh {

/// α = 2 sqrt(ε(2 − ε)): a chord of length αρ on a circle of radius ρ deviates from the arc by
/// at most ερ (relative chordal gap ε in (0, 1]).
double alpha_from_gap(double eps);
/// α = 2 sin θ: a chord of length αρ makes the angle θ (in (0, π/2]) with the tangent at its ends.
/// Same chord as the gap ε = 1 − cos θ.
double alpha_from_angle(double theta);

/// How close a discretisation must follow the geometry: a relative gap ε or a maximal angle θ.
struct GeometricTolerance {
  enum Kind { kRelativeGap, kAngle } kind = kRelativeGap;
  double value = 0.01;

  /// The size factor α (size = α · radius of curvature); throws InputError when out of range.
  double alpha() const;
  /// The relative gap ε (1 − cos θ for an angle).
  double relative_gap() const;
};

/// Local geometry of a parametric curve γ(t) at one point, from γ', γ'', γ'''.
template <int D>
struct CurveGeometry {
  double curvature = 0.0;  ///< κ = |γ' × γ''| / |γ'|³
  double radius = 0.0;     ///< ρ = 1/κ, +inf on a straight piece
  double torsion = 0.0;  ///< τ = (γ' × γ'')·γ''' / |γ' × γ''|²; 0 in 2D and on planar curves
  /// R = sqrt(ρ² + (ρ'σ)²), σ = 1/τ; equal to ρ where τ = 0 (the osculating circle).
  double osculating_sphere_radius = 0.0;
  double radius_derivative = 0.0;  ///< ρ' = dρ/ds (arc length s); 0 on a straight piece
};

/// Curvature, torsion and radii from the first three derivatives of any regular parametrisation.
/// Throws InputError("singular parametrisation") when γ' = 0 or a derivative is not finite.
template <int D>
CurveGeometry<D> curve_geometry(const Vec<D>& d1, const Vec<D>& d2, const Vec<D>& d3);

/// Tangential size α·ρ, or α·R when `torsion_aware` (BOOK.md §1), clamped to [hmin, hmax];
/// hmax on a straight piece.
template <int D>
double curve_size(const CurveGeometry<D>& g, double alpha, double hmin, double hmax,
                  bool torsion_aware);

/// Local geometry of a parametric surface σ(u, v) at one point.
struct SurfaceGeometry {
  SymMat2 first_form;   ///< [⟨σu,σu⟩ ⟨σu,σv⟩; · ⟨σv,σv⟩]
  SymMat2 second_form;  ///< [⟨σuu,n⟩ ⟨σuv,n⟩; · ⟨σvv,n⟩]
  Vec3 normal;          ///< n = σu × σv / |σu × σv|
  Mat2 weingarten;      ///< M_σ⁻¹ N_σ (parameter space, not symmetric)
  /// Principal curvatures (signed with respect to n), |k1| >= |k2|.
  double k1, k2;
  /// Principal radii 1/|k|, rho1 <= rho2, +inf where k = 0.
  double rho1, rho2;
  /// Unit principal directions in space; (w1, w2, n) is a right-handed orthonormal frame (at an
  /// umbilic or flat point any such tangent pair).
  Vec3 w1, w2;
  /// The same directions in the parameter plane: Dσ w1_uv = w1, Dσ w2_uv = w2.
  Vec2 w1_uv, w2_uv;
};

/// Fundamental forms, normal and principal curvatures from σu, σv, σuu, σuv, σvv. Throws
/// InputError("singular parametrisation") when σu and σv are (nearly) parallel.
SurfaceGeometry surface_geometry(const Vec3& su, const Vec3& sv, const Vec3& suu, const Vec3& suv,
                                 const Vec3& svv);

/// Isotropic geometric metric I/h², h = α min(ρ1, ρ2) clamped to [hmin, hmax].
SymMat3 surface_metric_isotropic(const SurfaceGeometry& g, const GeometricTolerance& tol,
                                 double hmin, double hmax);

/// Anisotropic geometric metric in the frame (w1, w2, n): sizes h1 = αρ1 along w1, h2 along w2,
/// hn = h1 along the normal (the smallest tangential size: the surface imposes nothing normally,
/// and a volume mesher then sees no flattened elements at the surface), all clamped to
/// [hmin, hmax]. h2 = h1 + f (βρ2 − h1), β = 2 sqrt(ε'(2 − ε')), ε' = ερ1/ρ2: f = 0 gives the
/// isotropic metric, f = 1 the full anisotropic one with the same absolute gap ερ1 in every
/// direction; every f in [0, 1] is geometric (gap <= ερ1), which lets the metric be fitted
/// inside another one (BOOK.md §1). Throws InputError for f outside [0, 1].
SymMat3 surface_metric_anisotropic(const SurfaceGeometry& g, const GeometricTolerance& tol,
                                   double hmin, double hmax, double beta_prime_fraction);

/// The metric induced in the parameter plane, Dσᵀ M Dσ (BOOK.md §3–7: parametric patches are
/// meshed in the parameter plane under it).
SymMat2 induced_metric(const SymMat3& m, const Vec3& su, const Vec3& sv);

}  // namespace riemesh
