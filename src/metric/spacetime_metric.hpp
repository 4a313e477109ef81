#pragma once
// Unsteady adaptation (BOOK.md §8, "Unsteady"): [0, T] is split into sub-intervals I_1..I_n,
// each with its own mesh, adapted in a fixed-point loop over the whole simulation. On I_i the
// Hessians of several time samples t_k are combined into one tensor field H_i, then
//
//   intersection (L∞ in time):  each sample's metric, intersected (combine_metrics), or
//   Lp space–time combination:  the global optimum below.
//
// The space–time Lp metric (Alauzet, Loseille & Olivier, "Multi-scale anisotropic mesh adaptation
// for time-dependent problems", INRIA RR-8929, 2016; continuous-mesh framework as in BOOK.md §2).
// Error model: E = Σ_i ∫_Ω tr(M_i^{-1/2} H_i M_i^{-1/2})^p dx with H_i the time-combined Hessian
// of I_i, either the time integral ∫_{I_i} |H| dt (trapezoid rule over the samples) or
// |I_i| · ∩_k |H(t_k)| (the max over the samples, an upper bound of the integral). Cost: the
// space–time complexity N_st = Σ_i n_i C(M_i), with n_i the solver's time steps in I_i and
// C(M) = ∫ sqrt(det M). Minimising E under that constraint (Lagrange, as in the steady case) gives
//
//   M_i = N_st^{2/d} (Σ_j n_j^{2p/(2p+d)} ∫_Ω det(H_j)^{p/(2p+d)})^{-2/d}
//         · n_i^{-2/(2p+d)} det(H_i)^{-1/(2p+d)} H_i,
//
// i.e. each sub-interval gets the steady Lp metric of H_i (the same shape) with the complexity
//
//   N_i = N_st n_i^{-d/(2p+d)} I_i / Σ_j n_j^{2p/(2p+d)} I_j,   I_j = ∫_Ω det(H_j)^{p/(2p+d)}
//
// (check: Σ n_i N_i = N_st). We ask for N̄ = N_st / Σ n_i, the mean complexity per time step
// (with a single interval, N̄ is the usual N), and build each M_i with hessian_metric for N_i,
// so clipping by hmin/hmax is handled as in the steady case and Σ n_i C(M_i) / Σ n_i = N̄
// whenever the bounds allow each N_i.
#include <span>
#include <vector>

#include "core/symmat.hpp"
#include "mesh/mesh.hpp"
#include "metric/hessian_metric.hpp"

namespace riemesh {

/// How the samples of a sub-interval are combined into H_i.
enum class TimeCombination {
  kMax,       ///< |I_i| · ∩_k |H(t_k)| (intersection of the absolute Hessians, L∞ in time)
  kIntegral,  ///< ∫_{I_i} |H| dt by the trapezoid rule over equally spaced samples (ends included)
};

/// |H| with its absolute eigenvalues raised to `floor` (so that it is SPD).
template <int D>
SymMat<D> abs_hessian(const SymMat<D>& h, double floor);

/// H_i of one sub-interval of length `length` from the Hessians of its samples (equally spaced,
/// first and last at the ends of the interval; one sample stands for the whole interval), on the
/// same vertices. Absolute eigenvalues are floored at 1e-12 of the largest over all samples;
/// samples all zero give H_i = 0 (no interpolation error: the sub-interval takes almost none of
/// the complexity, and the coarsest metric its bounds allow).
/// Throws InputError for no sample, samples of different sizes, non-finite values or
/// length <= 0.
template <int D>
std::vector<SymMat<D>> combine_in_time(std::span<const std::vector<SymMat<D>>> samples,
                                       double length, TimeCombination how);

/// ∫_Ω det(H)^{p/(2p+d)} by P1 quadrature (p = +inf: ∫ sqrt(det H)).
template <int D>
double lp_shape_integral(const Mesh& mesh, std::span<const SymMat<D>> h, double norm);

/// One sub-interval for spacetime_lp_metrics: its mesh, its H_i (combine_in_time) and its
/// number of time steps n_i (> 0; any positive unit, only ratios matter with N̄).
template <int D>
struct SpaceTimeInterval {
  const Mesh* mesh = nullptr;
  std::span<const SymMat<D>> hessian;
  double time_steps = 1.0;
};

/// The complexities N_i of the formula above for a mean complexity N̄ (options.complexity) and
/// norm p (options.norm, finite). Throws InputError for bad options or no interval.
template <int D>
std::vector<double> spacetime_complexities(std::span<const SpaceTimeInterval<D>> intervals,
                                           double mean_complexity, double norm);

/// The space–time Lp metric of every sub-interval: hessian_metric(mesh_i, H_i) for N_i, with the
/// norm, hmin, hmax and aniso_max of `options` (options.complexity is N̄). Reports per interval
/// when `reports` is given.
template <int D>
std::vector<std::vector<SymMat<D>>> spacetime_lp_metrics(
    std::span<const SpaceTimeInterval<D>> intervals, const HessianMetricOptions& options,
    std::vector<MetricReport>* reports = nullptr);

}  // namespace riemesh
