#include "attiguard/reach/closed_loop.hpp"

#include <cmath>
#include <stdexcept>

#include "attiguard/core/errors.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"
#include "attiguard/reach/interval_matrix.hpp"
#include "attiguard/reach/lmi_proof.hpp"

namespace attiguard::reach {

namespace {

/// |B| rad(ω) for an interval B over a box, plus the mean-value bound of the A-term.
Box3 mean_value_box(const Vec3& center_value, const IntervalMat3& A, double rho,
                    const IntervalMat3& B, const Box3& box) {
  const Mat3 Aabs = A.abs_max();
  const Mat3 Babs = B.abs_max();
  Vec3 rad = Babs * box.radius();
  for (int k = 0; k < 3; ++k) {
    rad(k) += Aabs.row(k).norm() * rho;
  }
  return Box3::around(center_value, rad);
}

/// G_k = J⁻¹((J e_k)^ − ê_k J), enclosed: the gyroscopic Jacobian is Σ_k ω_k G_k.
std::array<IntervalMat3, 3> gyroscopic_basis(const Mat3& J, const IntervalMat3& Jinv) {
  // rounding site: gyroscopic-basis
  std::array<IntervalMat3, 3> G;
  const IMat3 Ji = to_imat(Jinv);
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = Vec3::Unit(k);
    // (J e_k)^ and ê_k J are exact (entries ±J_ij); their difference and the product are not.
    const IMat3 D = add<3>(point<3>(lie::hat(J * e)), point<3>(Mat3(lie::hat(e) * J)), -1.0);
    G[static_cast<std::size_t>(k)] = to_interval_mat(product<3>(Ji, D));
  }
  return G;
}

/// Enclosure of Σ_k ω_k G_k over a box (each entry is linear in ω: its range over the box is
/// Σ_k [lo_k, hi_k] G_k,ij, enclosed with outward rounding).
IMat3 gyroscopic_enclosure(const std::array<IntervalMat3, 3>& G, const Box3& box) {
  // rounding site: gyroscopic-enclosure
  IMat3 out = point<3>(Mat3(Mat3::Zero()));
  for (int k = 0; k < 3; ++k) {
    const Interval wk(box.lo(k), box.hi(k));
    out = add<3>(out, scaled<3>(wk, to_imat(G[static_cast<std::size_t>(k)])));
  }
  return out;
}

/// The entrywise enclosure of the exact Σ_k w_k G_k − k_d J⁻¹ at a point w (k_d = 0: the
/// torque-free B).
IMat3 b_at(const std::array<IntervalMat3, 3>& G, const IntervalMat3& Jinv, double kd, const Vec3& w) {
  const IMat3 g = gyroscopic_enclosure(G, Box3{w, w});
  if (kd == 0.0) return g;
  return add<3>(g, scaled<3>(Interval(kd), to_imat(Jinv)), -1.0);
}

/// Bounds on the change of E = Rᵀ R_g from E_c = R_cᵀ R_g over the ball: ‖ΔE‖₂ ≤ s and
/// |Δ tr E| ≤ dtr. The floating-point R_c and R_g need not be rotations; the ball is read as
/// {U exp(η̂) : ‖η‖ ≤ ρ}, U the polar factor of R_c (as the safety check reads it, safety.cpp).
struct EDeviation {
  double s{0.0};
  double dtr{0.0};
};

EDeviation e_deviation(const Mat3& Rc, const Mat3& Rg, double rho) {
  // rounding site: a-deviation
  // ΔE = (Q − I) UᵀR_g + (U − R_c)ᵀR_g, Q = exp(−η̂): ‖Q − I‖₂ ≤ ch = 2 sin(ρ/2),
  // ‖Q − I‖_F ≤ √2 ch. ‖U − R_c‖_F ≤ e_c = ‖R_cᵀR_c − I‖_F and R_g = V_g + D_g, V_g orthogonal,
  // ‖D_g‖_F ≤ e_g, ‖R_g‖₂ ≤ 1 + e_g. tr((Q − I)UᵀV_g) = ±Δ(1 + 2 cos θ), |Δθ| ≤ ρ: ≤ 2ρ;
  // tr((Q − I)UᵀD_g) ≤ √2 ch e_g (Cauchy–Schwarz), or the whole ≤ √2 ch ‖R_g‖_F;
  // |tr D'| ≤ √3 ‖D'‖_F, ‖D'‖_F ≤ e_c (1 + e_g).
  const IMat3 Rgi = point<3>(Rg);
  const Interval ch(chord_up(rho));
  const Interval eg(orthogonality_defect_up(Rgi));
  const Interval ec(orthogonality_defect_up(point<3>(Rc)));
  const Interval one(1.0);
  const Interval sqrt2(sqrt_down(2.0), sqrt_up(2.0));
  const Interval sqrt3(sqrt_down(3.0), sqrt_up(3.0));
  const Interval dprime = ec * (one + eg);
  EDeviation d;
  d.s = (ch * (one + eg) + dprime).hi;
  const double via_rho = (Interval(2.0) * Interval(rho) + sqrt2 * ch * eg).hi;
  const double via_frobenius = (sqrt2 * ch * Interval(frobenius_up<3>(Rgi))).hi;
  d.dtr = (Interval(std::min(via_rho, via_frobenius)) + sqrt3 * dprime).hi;
  return d;
}

/// Entrywise upper bound of |ΔA| = (|k_p|/2) |J⁻¹ (Δtr I − ΔE)| ≤ (|k_p|/2) |J⁻¹| (dtr I + s 1).
Mat3 a_deviation_entrywise(const IntervalMat3& Jinv, double kp, const EDeviation& d) {
  IMat3 D;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) D[i][j] = i == j ? Interval(d.dtr) + Interval(d.s) : Interval(d.s);
  }
  const IMat3 out = scaled<3>(Interval(0.5 * std::abs(kp)), product<3>(point<3>(Mat3(Jinv.abs_max())), D));
  return magnitudes(out);
}

/// [c ± rad] entrywise, outward.
IntervalMat3 inflate(const IMat3& c, const Mat3& rad) {
  IMat3 out = c;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      const double r = rad(static_cast<int>(i), static_cast<int>(j));
      out[i][j] = out[i][j] + Interval(-r, r);
    }
  }
  return to_interval_mat(out);
}

}  // namespace

double inverse_spectral_bound(const Mat3& J) {
  // rounding site: j-inverse-norm
  double bound = frobenius_up<3>(to_imat(enclose_inverse(J)));
  const Vec3 moments = lie::symmetric_eigenvalues(J);
  const double scale = J.cwiseAbs().maxCoeff();
  for (int k = 0; k < 12; ++k) {
    const double mu = moments(0) - scale * 1e-15 * std::pow(4.0, k);
    if (!(mu > 0.0)) break;
    if (prove_less(Mat3(mu * Mat3::Identity()), J).proved) {  // μI ≺ J: λ_min(J) > μ
      bound = std::min(bound, (Interval(1.0) / mu).hi);
      break;
    }
  }
  return bound;
}

IntervalMat3 enclose_inverse(const Mat3& J) {
  // rounding site: j-inverse
  const Mat3 X = J.inverse();
  if (!X.allFinite()) throw NumericalError("ConReach: the inertia matrix has no finite inverse");
  const IMat3 Xi = point<3>(X);
  const IMat3 E = add<3>(point<3>(Mat3(Mat3::Identity())), product<3>(point<3>(J), Xi), -1.0);
  const double e = inf_norm_up<3>(E);
  if (!(e < 0.5)) {
    throw NumericalError("ConReach: the inertia matrix is too ill-conditioned to enclose its inverse");
  }
  // J⁻¹ − X = X (I − E)⁻¹ E: ‖·‖_∞ ≤ ‖X‖ ‖E‖ / (1 − ‖E‖), a bound on every entry.
  const double r = ((Interval(inf_norm_up<3>(Xi)) * Interval(e)) / (Interval(1.0) - Interval(e)).lo).hi;
  return inflate(Xi, Mat3::Constant(r));
}

PolynomialField ClosedLoop::polynomial_field() const {
  const std::optional<PolynomialField> f =
      probe_polynomial_field([this](const Mat3& R, const Vec3& w) { return omega_dot(R, w); });
  if (!f) {
    throw NumericalError("ConReach: closed loop '" + name() +
                         "' is not a polynomial c + B w + (w^T Q_a w) + L vec(R) (reach/polynomial_field.hpp)");
  }
  return *f;
}

Box3 ClosedLoop::omega_dot_enclosure(const AttitudeBall& att, const Box3& box) const {
  return mean_value_box(omega_dot(att.center, box.center()), A_enclosure(att, box), att.radius,
                        B_enclosure(att, box), box);
}

// ---- LinearOmegaLoop -------------------------------------------------------------------------

LinearOmegaLoop::LinearOmegaLoop(const Mat3& M)
    : ClosedLoop({.lmi_depends_on_attitude = false, .omega_flow_affine = true}), M_(M) {
  if (!M.allFinite()) throw InputError("linear_omega: non-finite matrix");
}
Vec3 LinearOmegaLoop::omega_dot(const Mat3&, const Vec3& omega) const { return M_ * omega; }
Mat3 LinearOmegaLoop::A(const Mat3&, const Vec3&) const { return Mat3::Zero(); }
Mat3 LinearOmegaLoop::B(const Mat3&, const Vec3&) const { return M_; }
IntervalMat3 LinearOmegaLoop::A_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(Mat3::Zero());
}
IntervalMat3 LinearOmegaLoop::B_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(M_);
}
LmiEnclosure LinearOmegaLoop::lmi_enclosure(const AttitudeBall&, const Box3& box) const {
  // A = 0 and B = M are constant and ω̂ is linear in ω: the 8 vertices are exact.
  LmiEnclosure e;
  e.exact = true;
  for (int v = 0; v < 8; ++v) e.vertices.push_back({box.vertex(v), Mat3::Zero(), M_});
  return e;
}

// ---- RigidBodyLoop ---------------------------------------------------------------------------

RigidBodyLoop::RigidBodyLoop(const Mat3& J, const Vec3& torque_b)
    : ClosedLoop({.lmi_depends_on_attitude = false, .omega_flow_affine = false}),
      body_(J), tau_(torque_b), Jinv_(enclose_inverse(body_.inertia())),
      G_(gyroscopic_basis(body_.inertia(), Jinv_)) {
  if (!torque_b.allFinite()) throw InputError("rigid body: non-finite torque");
}
std::string RigidBodyLoop::name() const { return tau_.isZero(0.0) ? "free" : "constant_torque"; }
Vec3 RigidBodyLoop::omega_dot(const Mat3&, const Vec3& w) const {
  return body_.angular_acceleration(w, tau_);
}
Mat3 RigidBodyLoop::A(const Mat3&, const Vec3&) const { return Mat3::Zero(); }
Mat3 RigidBodyLoop::B(const Mat3&, const Vec3& w) const {
  const Mat3& J = body_.inertia();
  return body_.inertia_inverse() * (lie::hat(J * w) - lie::hat(w) * J);
}
IntervalMat3 RigidBodyLoop::A_enclosure(const AttitudeBall&, const Box3&) const {
  return IntervalMat3::point(Mat3::Zero());
}
IntervalMat3 RigidBodyLoop::B_enclosure(const AttitudeBall&, const Box3& box) const {
  return to_interval_mat(gyroscopic_enclosure(G_, box));
}
LmiEnclosure RigidBodyLoop::lmi_enclosure(const AttitudeBall&, const Box3& box) const {
  // A = 0, B is linear in ω, ω̂ is linear in ω, nothing depends on R: vertices are exact up to
  // the rounding of B_v, which B_rad encloses.
  LmiEnclosure e;
  e.exact = true;
  for (int v = 0; v < 8; ++v) {
    const Vec3 w = box.vertex(v);
    LmiVertex vx{w, Mat3::Zero(), B(Mat3::Identity(), w)};
    // rounding site: vertex-data
    vx.B_rad = radius_about(b_at(G_, Jinv_, 0.0, w), vx.B);
    e.vertices.push_back(vx);
  }
  return e;
}

// ---- PdLoop ----------------------------------------------------------------------------------

PdLoop::PdLoop(const Mat3& J, double kp, double kd, const Mat3& R_g)
    : ClosedLoop({.lmi_depends_on_attitude = true, .omega_flow_affine = false}),
      body_(J), Rg_(R_g), gains_{kp, kd}, Jinv_(enclose_inverse(body_.inertia())),
      jinv_norm2_(inverse_spectral_bound(body_.inertia())), G_(gyroscopic_basis(body_.inertia(), Jinv_)) {
  if (!std::isfinite(kp) || !std::isfinite(kd) || !R_g.allFinite()) {
    throw InputError("pd: non-finite gains or reference");
  }
}
Vec3 PdLoop::omega_dot(const Mat3& R, const Vec3& w) const {
  return body_.angular_acceleration(w, control::pd_torque(R, w, Rg_, gains_));
}
Mat3 PdLoop::A(const Mat3& R, const Vec3&) const {
  // d/dt vee(sk(exp(−tα̂) E)) = −½ vee(α̂E + Eᵀα̂) = −½ (tr(E) I − E) α.
  const Mat3 E = R.transpose() * Rg_;
  return -0.5 * gains_.kp * body_.inertia_inverse() * (E.trace() * Mat3::Identity() - E);
}
Mat3 PdLoop::B(const Mat3&, const Vec3& w) const {
  const Mat3& J = body_.inertia();
  return body_.inertia_inverse() * (lie::hat(J * w) - lie::hat(w) * J - gains_.kd * Mat3::Identity());
}

namespace {
/// E_c = R_cᵀ R_g and the exact A(R_c) = −(k_p/2) J⁻¹ (tr(E_c) I − E_c), enclosed.
struct PdCentre {
  IMat3 E;
  IMat3 A;
};
PdCentre pd_centre(const Mat3& Rc, const Mat3& Rg, const IntervalMat3& Jinv, double kp) {
  PdCentre c;
  c.E = product<3>(transposed<3>(point<3>(Rc)), point<3>(Rg));
  const Interval tr = c.E[0][0] + c.E[1][1] + c.E[2][2];
  IMat3 T;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) T[i][j] = (i == j ? tr : Interval(0.0)) - c.E[i][j];
  }
  c.A = scaled<3>(Interval(-0.5 * kp), product<3>(to_imat(Jinv), T));  // −0.5 k_p is exact
  return c;
}
}  // namespace

IntervalMat3 PdLoop::A_enclosure(const AttitudeBall& att, const Box3&) const {
  // R = U exp(η̂), ‖η‖ ≤ ρ (U the polar factor of R_c): ‖ΔE‖₂ ≤ s, |Δ tr E| ≤ dtr (e_deviation), so
  // |ΔA| ≤ (k_p/2)|J⁻¹|(dtr I + s 1) entrywise, about the enclosure of A(R_c).
  // rounding site: a-enclosure
  const PdCentre c = pd_centre(att.center, Rg_, Jinv_, gains_.kp);
  return inflate(c.A, a_deviation_entrywise(Jinv_, gains_.kp, e_deviation(att.center, Rg_, att.radius)));
}
double PdLoop::a_deviation_bound(const AttitudeBall& att) const {
  // rounding site: a-deviation
  const EDeviation d = e_deviation(att.center, Rg_, att.radius);
  // ‖ΔA‖₂ ≤ (k_p/2) ‖J⁻¹‖₂ (dtr + s), or the Frobenius norm of the entrywise bound.
  const double spectral =
      (Interval(0.5 * std::abs(gains_.kp)) * Interval(jinv_norm2_) * (Interval(d.dtr) + Interval(d.s))).hi;
  const double frobenius = frobenius_up<3>(point<3>(a_deviation_entrywise(Jinv_, gains_.kp, d)));
  return std::min(spectral, frobenius);
}
IntervalMat3 PdLoop::B_enclosure(const AttitudeBall&, const Box3& box) const {
  // rounding site: b-enclosure
  return to_interval_mat(
      add<3>(gyroscopic_enclosure(G_, box), scaled<3>(Interval(gains_.kd), to_imat(Jinv_)), -1.0));
}
LmiEnclosure PdLoop::lmi_enclosure(const AttitudeBall& att, const Box3& box) const {
  // B and ω̂ are affine in ω and independent of R: vertices of the box, exact up to the rounding
  // of B_v. A depends on R only: its centre at every vertex (up to the rounding of A_v) and
  // ‖A − A(R_c)‖₂ ≤ rho handled by the robust LMI.
  LmiEnclosure e;
  e.exact = false;
  const Mat3 Ac = A(att.center, Vec3::Zero());
  // rounding site: vertex-data
  const Mat3 Ac_rad = radius_about(pd_centre(att.center, Rg_, Jinv_, gains_.kp).A, Ac);
  for (int v = 0; v < 8; ++v) {
    const Vec3 w = box.vertex(v);
    LmiVertex vx{w, Ac, B(Mat3::Identity(), w)};
    vx.A_rad = Ac_rad;
    vx.B_rad = radius_about(b_at(G_, Jinv_, gains_.kd, w), vx.B);
    e.vertices.push_back(vx);
  }
  e.rho = a_deviation_bound(att);
  return e;
}

}  // namespace attiguard::reach
