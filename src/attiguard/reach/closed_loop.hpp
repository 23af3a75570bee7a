#pragma once
/// @file closed_loop.hpp
/// Closed-loop attitude dynamics X(R, ω) = (R ω̂, X_ω(R, ω)) on SO(3) × R³
/// [ConReach eq. (6)] with the matrices of Theorem 4:
///   A(R, ω) α = d/dt X_ω(R exp(t α̂), ω)|₀,   B(R, ω) = ∂X_ω/∂ω,
/// and sound enclosures of A, B and X_ω over a set {R : d(R, R_c) ≤ ρ} × box(ω).
///
/// Built-in closed loops:
///  - LinearOmegaLoop: X_ω = M ω (the paper's Sec. 6 example, M = J = diag(−2, −1, −3));
///    A = 0, B = M. M is a linear ω-dynamics matrix, not an inertia.
///  - RigidBodyLoop:   J ω̇ = −ω × Jω + τ with τ constant (0: torque-free; the plant of
///    dynamics::RigidBody); A = 0, B = J⁻¹((Jω)^ − ω̂ J), affine in ω.
///  - PdLoop:          that plant under control::pd_torque, τ = k_p sk(Rᵀ R_g)^∨ − k_d ω
///    [PET-ERG eq. (3)] to a fixed R_g; A = −(k_p/2) J⁻¹ (tr(E) I − E), E = Rᵀ R_g;
///    B = J⁻¹((Jω)^ − ω̂ J − k_d I).
/// docs/reach.md derives A and B; tests/reach/test_reach_closed_loop.cpp checks them against finite
/// differences.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/control/pd_so3.hpp"
#include "attiguard/reach/interval.hpp"
#include "attiguard/reach/polynomial_field.hpp"

namespace attiguard::reach {

/// One vertex of the LMI data: (ω_v, A_v, B_v) and entrywise radii such that the exact
/// (A, B) the vertex stands for lie in [A_v ± A_rad] × [B_v ± B_rad] (the rounding of the
/// floating-point computation of A_v, B_v; docs/reach.md, "Rounding sites"). ω_v is exact.
struct LmiVertex {
  Vec3 omega{Vec3::Zero()};
  Mat3 A{Mat3::Zero()};
  Mat3 B{Mat3::Zero()};
  Mat3 A_rad{Mat3::Zero()};
  Mat3 B_rad{Mat3::Zero()};
};

/// What the contraction LMI [ConReach eq. (10)] must hold for, over a set U: for every (R, ω) ∈ U there are
/// convex weights θ_v and Δ = [ΔA ΔB] (3×6) with ‖Δ‖₂ ≤ rho such that
///   (A(R, ω), B(R, ω), ω) = Σ_v θ_v (A_v, B_v, ω_v) + (ΔA, ΔB, 0).
/// Since (10) is affine in (A, B, ω̂) for fixed (Q, P, c), imposing it at every vertex robustly
/// against ‖Δ‖ ≤ rho imposes it on U. rho = 0 and `exact` when the LMI is affine in ω alone
/// (vertex enumeration, docs/errata.md, ConReach 2).
struct LmiEnclosure {
  std::vector<LmiVertex> vertices;
  double rho{0.0};
  bool exact{false};
};

/// A verified enclosure of J⁻¹ for a nonsingular J (docs/reach.md, "Rounding sites"): X the
/// floating-point inverse, E = I − JX in interval arithmetic, and
/// ‖J⁻¹ − X‖_∞ ≤ ‖X‖_∞‖E‖_∞ / (1 − ‖E‖_∞) added to every entry. Throws NumericalError when
/// ‖E‖_∞ ≥ ½ (J too ill-conditioned for the bound).
[[nodiscard]] IntervalMat3 enclose_inverse(const Mat3& J);
/// An upper bound of ‖J⁻¹‖₂ = 1/λ_min(J) for a symmetric positive definite J (docs/reach.md,
/// "Rounding sites"): 1/μ for a μ slightly below the floating-point λ_min with μI ≺ J proved in
/// interval arithmetic (lmi_proof.hpp), or the Frobenius norm of enclose_inverse(J) when smaller.
[[nodiscard]] double inverse_spectral_bound(const Mat3& J);

/// A closed loop X_ω with analytic A, B and their enclosures.
class ClosedLoop {
 public:
  virtual ~ClosedLoop() = default;
  /// Model name as in the scenario key `system.model`.
  [[nodiscard]] virtual std::string name() const = 0;
  [[nodiscard]] virtual Vec3 omega_dot(const Mat3& R, const Vec3& omega) const = 0;
  [[nodiscard]] virtual Mat3 A(const Mat3& R, const Vec3& omega) const = 0;
  [[nodiscard]] virtual Mat3 B(const Mat3& R, const Vec3& omega) const = 0;
  /// Sound entrywise enclosures over {R : d(R, att.center) ≤ att.radius} × box, outward-rounded
  /// (a float centre read through its polar factor; docs/reach.md, "Rounding sites").
  [[nodiscard]] virtual IntervalMat3 A_enclosure(const AttitudeBall& att, const Box3& box) const = 0;
  [[nodiscard]] virtual IntervalMat3 B_enclosure(const AttitudeBall& att, const Box3& box) const = 0;
  /// LMI data over the same set (see LmiEnclosure).
  [[nodiscard]] virtual LmiEnclosure lmi_enclosure(const AttitudeBall& att, const Box3& box) const = 0;
  /// True when A or B depends on R (then the LMI needs an attitude enclosure).
  [[nodiscard]] bool lmi_depends_on_attitude() const noexcept { return structure_.lmi_depends_on_attitude; }
  /// True when X_ω = M ω + b independently of R: the ω-flow is affine (ω-reach sets of convex
  /// sets stay convex).
  [[nodiscard]] bool omega_flow_affine() const noexcept { return structure_.omega_flow_affine; }
  /// X_ω as the exact polynomial it is (polynomial_field.hpp), read off omega_dot: what the
  /// bound on the nominal's integration error differentiates. Every built-in loop is of that
  /// form; throws NumericalError for a loop that is not.
  [[nodiscard]] PolynomialField polynomial_field() const;

  /// Mean-value enclosure of X_ω over the set: X_ω(R_c, ω_c) ± (‖row_k |A|‖ ρ + |B| rad(ω)).
  [[nodiscard]] Box3 omega_dot_enclosure(const AttitudeBall& att, const Box3& box) const;

 protected:
  /// The structure of a concrete loop's X_ω, fixed by its model.
  struct Structure {
    bool lmi_depends_on_attitude{false};  ///< see lmi_depends_on_attitude()
    bool omega_flow_affine{false};        ///< see omega_flow_affine()
  };
  explicit ClosedLoop(Structure structure) noexcept : structure_(structure) {}

 private:
  Structure structure_;
};

/// X_ω = M ω (paper, Sec. 6).
class LinearOmegaLoop final : public ClosedLoop {
 public:
  explicit LinearOmegaLoop(const Mat3& M);
  [[nodiscard]] std::string name() const override { return "linear_omega"; }
  [[nodiscard]] Vec3 omega_dot(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] Mat3 A(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] Mat3 B(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] IntervalMat3 A_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] IntervalMat3 B_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] LmiEnclosure lmi_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] const Mat3& matrix() const noexcept { return M_; }

 private:
  Mat3 M_;
};

/// J ω̇ = −ω × Jω + τ, τ constant (zero: torque-free).
class RigidBodyLoop final : public ClosedLoop {
 public:
  RigidBodyLoop(const Mat3& J, const Vec3& torque_b);
  [[nodiscard]] std::string name() const override;
  [[nodiscard]] Vec3 omega_dot(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] Mat3 A(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] Mat3 B(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] IntervalMat3 A_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] IntervalMat3 B_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] LmiEnclosure lmi_enclosure(const AttitudeBall& att, const Box3& box) const override;

 private:
  dynamics::RigidBody body_;
  Vec3 tau_;
  IntervalMat3 Jinv_;              ///< enclose_inverse(J)
  std::array<IntervalMat3, 3> G_;  ///< B(ω) = Σ_k ω_k G_k, enclosed
};

/// PD law [PET-ERG eq. (3)] towards a fixed R_g.
class PdLoop final : public ClosedLoop {
 public:
  PdLoop(const Mat3& J, double kp, double kd, const Mat3& R_g);
  [[nodiscard]] std::string name() const override { return "pd"; }
  [[nodiscard]] Vec3 omega_dot(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] Mat3 A(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] Mat3 B(const Mat3& R, const Vec3& omega) const override;
  [[nodiscard]] IntervalMat3 A_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] IntervalMat3 B_enclosure(const AttitudeBall& att, const Box3& box) const override;
  [[nodiscard]] LmiEnclosure lmi_enclosure(const AttitudeBall& att, const Box3& box) const override;
  /// Upper bound, valid for the real numbers (outward rounding, docs/reach.md "Rounding sites"), on
  /// ‖A(R, ·) − A(R_c, ·)‖₂ over the attitude ball (A does not depend on ω).
  [[nodiscard]] double a_deviation_bound(const AttitudeBall& att) const;

 private:
  dynamics::RigidBody body_;
  Mat3 Rg_;
  control::PdGains gains_;
  IntervalMat3 Jinv_;              ///< enclose_inverse(J)
  double jinv_norm2_{0.0};         ///< upper bound of ‖J⁻¹‖₂
  std::array<IntervalMat3, 3> G_;  ///< gyroscopic part of B: Σ_k ω_k G_k, enclosed
};

}  // namespace attiguard::reach
