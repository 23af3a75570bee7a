#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/read_rigid_body.hpp"
#include "scenario/scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

using test::contains;
using test::input_error;
using test::starts_with;
using test::with_lines;

// A valid PD scenario; the tests below replace single lines, so the line numbers are stable.
constexpr std::string_view kPd = R"(kind = "rigid_body"
[body]
inertia = [1, 2, 3]
[initial]
attitude = { quaternion = [1, 0, 0, 0] }
omega_b = [0.2, 0.3, 0.4]
[control]
law = "pd"
kp = 5.0
kd = 1.0
reference = { axis = [0, 1, 0], angle_deg = 90 }
[simulation]
duration = 30.0
output_interval = 0.05
integrator = "rkmk4"
step = 0.01
)";

/// The error of parse_rigid_body on kPd with `replacements` applied, as file "bad.toml".
std::string error_of(const std::map<int, std::string>& replacements) {
  const std::string text = with_lines(kPd, replacements);
  return input_error([&] { (void)parse_rigid_body(parse_document(text, "bad.toml")); });
}

TEST(RigidBodyScenario, ParsesAValidPdScenario) {
  const sim::RigidBodyScenario sc = parse_rigid_body(parse_document(kPd, "dir/slew.toml"));
  EXPECT_EQ(sc.name, "slew");
  EXPECT_EQ(sc.J, Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix());
  EXPECT_LT((sc.R0_ib - lie::Mat3::Identity()).norm(), 1e-15);
  EXPECT_EQ(sc.omega0_b, lie::Vec3(0.2, 0.3, 0.4));
  EXPECT_EQ(sc.law, sim::TorqueLaw::pd);
  EXPECT_EQ(sc.kp, 5.0);
  EXPECT_EQ(sc.kd, 1.0);
  EXPECT_LT((sc.R_ref_ib * lie::Vec3::UnitX() - lie::Vec3(0, 0, -1)).norm(), 1e-15);
  EXPECT_EQ(sc.duration, 30.0);
  EXPECT_EQ(sc.output_interval, 0.05);
  EXPECT_EQ(sc.integrator.method, integrate::Method::rkmk4);
  EXPECT_EQ(sc.integrator.step, 0.01);
}

TEST(RigidBodyScenario, OptionalKeysTakeTheirDocumentedDefaults) {
  const sim::RigidBodyScenario sc = parse_rigid_body(parse_document(R"(kind = "rigid_body"
[body]
inertia = [[2, 0, 0], [0, 2, 0], [0, 0, 3]]
[control]
law = "free"
[simulation]
duration = 1
)",
                                                               "runs/tumble.toml"));
  const integrate::IntegratorSettings defaults;
  EXPECT_EQ(sc.name, "tumble");
  EXPECT_EQ(sc.R0_ib, lie::Mat3::Identity());
  EXPECT_EQ(sc.omega0_b, lie::Vec3::Zero());
  EXPECT_EQ(sc.law, sim::TorqueLaw::free);
  EXPECT_EQ(sc.duration, 1.0);
  EXPECT_EQ(sc.output_interval, 0.01);
  EXPECT_EQ(sc.integrator.method, integrate::Method::rkmk4);
  EXPECT_EQ(sc.integrator.step, 0.01);
  EXPECT_EQ(sc.integrator.abs_tol, 1e-9);
  EXPECT_EQ(sc.integrator.rel_tol, 1e-9);
  EXPECT_EQ(sc.integrator.max_step, 0.0);
  EXPECT_EQ(sc.integrator.min_step, defaults.min_step);
  EXPECT_EQ(sc.integrator.max_steps, defaults.max_steps);
}

TEST(RigidBodyScenario, ConstantTorqueAndAdaptiveIntegrator) {
  const sim::RigidBodyScenario sc = parse_rigid_body(parse_document(
      with_lines(
          kPd,
          {{1, "kind = \"rigid_body\"\nname = \"spin-up\"\ndescription = \"constant torque\""},
           {8, "law = \"constant_torque\"\ntorque_b = [0, 0, 0.1]"},
           {9, ""},
           {10, ""},
           {11, ""},
           {15, "integrator = \"rkmk_dp54\"\nabs_tol = 1e-8\nrel_tol = 1e-7\nmax_step = 0.5"}}),
      "x.toml"));
  EXPECT_EQ(sc.name, "spin-up");
  EXPECT_EQ(sc.law, sim::TorqueLaw::constant_torque);
  EXPECT_EQ(sc.torque_b, lie::Vec3(0, 0, 0.1));
  EXPECT_EQ(sc.integrator.method, integrate::Method::rkmk_dp54);
  EXPECT_EQ(sc.integrator.abs_tol, 1e-8);
  EXPECT_EQ(sc.integrator.rel_tol, 1e-7);
  EXPECT_EQ(sc.integrator.max_step, 0.5);
}

TEST(RigidBodyScenario, TypoOfARequiredKeyIsAnUnknownKeyAtItsPosition) {
  EXPECT_EQ(error_of({{9, "kpp = 5.0"}}),
            "bad.toml:9:1: control.kpp: unknown key 'kpp'; did you mean 'kp'? (required key 'kp' "
            "is missing)");
}

TEST(RigidBodyScenario, ExtraKeyIsUnknownAndTheKnownKeysAreListed) {
  EXPECT_EQ(error_of({{11, "reference = { axis = [0, 1, 0], angle_deg = 90 }\nkpp = 5.0"}}),
            "bad.toml:12:1: control.kpp: unknown key 'kpp' (expected one of: kd, kp, law, "
            "reference); did you mean 'kp'?");
  EXPECT_TRUE(
      starts_with(error_of({{16, "step = 0.01\noutput_intervall = 0.1"}}),
                  "bad.toml:17:1: simulation.output_intervall: unknown key "
                  "'output_intervall' (expected one of: abs_tol, duration, integrator, "
                  "max_step, output_interval, rel_tol, step); did you mean 'output_interval'?"));
  EXPECT_TRUE(starts_with(error_of({{4, "[initial]\nomega = [0, 0, 0]"}}),
                          "bad.toml:5:1: initial.omega: unknown key 'omega' (expected one of: "
                          "attitude, omega_b); did you mean 'omega_b'?"));
  EXPECT_TRUE(
      starts_with(error_of({{16, "step = 0.01\n[plot]\nx = 1"}}),
                  "bad.toml:17:2: plot: unknown key 'plot' (expected one of: body, control, "
                  "description, ephemeris, initial, kind, name, simulation)"));
}

TEST(RigidBodyScenario, KeysOfAnotherLawAreUnknown) {
  EXPECT_EQ(error_of({{8, "law = \"free\""}, {10, ""}, {11, ""}}),
            "bad.toml:9:1: control.kp: unknown key 'kp' (expected one of: law)");
  EXPECT_TRUE(starts_with(error_of({{8, "law = \"constant_torque\"\ntorque_b = [0, 0, 1]"}}),
                          "bad.toml:10:1: control.kp: unknown key 'kp' (expected one of: law, "
                          "torque_b)"));
  EXPECT_TRUE(
      starts_with(error_of({{8, "law = \"PD\""}}),
                  "bad.toml:8:7: control.law: must be one of \"free\", \"constant_torque\", "
                  "\"pd\", got \"PD\"; did you mean \"pd\"?"));
}

TEST(RigidBodyScenario, NonOrthonormalMatrixIsRejectedWithTheMeasuredError) {
  const std::string m =
      error_of({{5, "attitude = { matrix = [[1, 0, 0], [0, 1, 0.01], [0, 0, 1]] }"}});
  EXPECT_TRUE(starts_with(m,
                          "bad.toml:5:23: initial.attitude.matrix: not a rotation matrix: "
                          "||R^T R - I||_F = 0.0141"));
}

TEST(RigidBodyScenario, NanAndInfAreRejected) {
  EXPECT_EQ(error_of({{6, "omega_b = [0.2, nan, 0.4]"}}),
            "bad.toml:6:17: initial.omega_b[1]: must be finite, got nan");
  EXPECT_EQ(error_of({{13, "duration = inf"}}),
            "bad.toml:13:12: simulation.duration: must be finite, got inf");
  EXPECT_EQ(error_of({{10, "kd = -inf"}}), "bad.toml:10:6: control.kd: must be finite, got -inf");
}

TEST(RigidBodyScenario, NegativeOrZeroGainsAndStepsAreRejected) {
  EXPECT_EQ(error_of({{9, "kp = -1"}}), "bad.toml:9:6: control.kp: must be > 0, got -1");
  EXPECT_EQ(error_of({{10, "kd = 0"}}), "bad.toml:10:6: control.kd: must be > 0, got 0");
  EXPECT_EQ(error_of({{16, "step = -0.01"}}),
            "bad.toml:16:8: simulation.step: must be > 0, got -0.01");
  EXPECT_EQ(error_of({{16, "max_step = -1"}}),
            "bad.toml:16:12: simulation.max_step: must be >= 0, got -1");
  EXPECT_EQ(error_of({{16, "abs_tol = 0"}}),
            "bad.toml:16:11: simulation.abs_tol: must be > 0, got 0");
}

TEST(RigidBodyScenario, WrongTypesShapesAndEmptyArraysAreRejected) {
  EXPECT_EQ(error_of({{6, "omega_b = []"}}),
            "bad.toml:6:11: initial.omega_b: expected an array of 3 numbers, got an empty array");
  EXPECT_EQ(error_of({{6, "omega_b = [0.2, 0.3]"}}),
            "bad.toml:6:11: initial.omega_b: expected an array of 3 numbers, got 2 elements");
  EXPECT_EQ(error_of({{9, "kp = \"5\""}}),
            "bad.toml:9:6: control.kp: expected a number, got a string \"5\"");
  EXPECT_EQ(error_of({{3, "inertia = []"}}),
            "bad.toml:3:11: body.inertia: expected an inertia matrix [kg m^2]: principal moments "
            "[J1, J2, J3] or 3 rows of 3 numbers, got an empty array");
  EXPECT_TRUE(starts_with(error_of({{15, "integrator = 4"}}),
                          "bad.toml:15:14: simulation.integrator: expected one of \"rkmk4\", "
                          "\"rkmk_dp54\", got an integer"));
  EXPECT_TRUE(starts_with(error_of({{2, "body = 1"}, {3, ""}}),
                          "bad.toml:2:8: body: expected a table, got an integer"));
}

TEST(RigidBodyScenario, NonUnitQuaternionIsRejectedWithItsNorm) {
  EXPECT_EQ(error_of({{5, "attitude = { quaternion = [1, 0, 0, 0.5] }"}}),
            "bad.toml:5:27: initial.attitude.quaternion: not a unit quaternion: norm = "
            "1.118033988749895 (must be 1 to within 1e-9)");
}

TEST(RigidBodyScenario, TwoRotationFormsAreRejected) {
  EXPECT_TRUE(starts_with(
      error_of(
          {{11, "reference = { axis = [0, 1, 0], angle_deg = 90, quaternion = [1, 0, 0, 0] }"}}),
      "bad.toml:11:13: control.reference: 2 rotation forms given (quaternion and axis): expected "
      "exactly one of: matrix"));
}

TEST(RigidBodyScenario, NonPhysicalInertiaIsRejectedAtTheKey) {
  EXPECT_EQ(
      error_of({{3, "inertia = [1, 1, 3]"}}),
      "bad.toml:3:11: body.inertia: principal moments 1, 1, 3 violate the triangle inequality "
      "J1 + J2 >= J3 (no physical body has them)");
  EXPECT_TRUE(starts_with(error_of({{3, "inertia = [1, 0, 1]"}}),
                          "bad.toml:3:11: body.inertia: inertia matrix is not positive definite"));
}

TEST(RigidBodyScenario, MissingRequiredKeysAreLocatedAtTheirTable) {
  EXPECT_EQ(error_of({{13, ""}}),
            "bad.toml:12:1: simulation.duration: missing required key (expected a number > 0)");
  EXPECT_TRUE(starts_with(error_of({{11, ""}}),
                          "bad.toml:7:1: control.reference: missing required key (expected a "
                          "rotation table"));
  EXPECT_EQ(error_of({{2, ""}, {3, ""}}),
            "bad.toml:1:1: body: missing required key (expected a table [body])");
  EXPECT_TRUE(starts_with(error_of({{7, "[contrl]"}}),
                          "bad.toml:7:2: contrl: unknown key 'contrl'; did you mean 'control'? "
                          "(required key 'control' is missing)"));
}

TEST(RigidBodyScenario, WrongKindIsRejected) {
  EXPECT_EQ(error_of({{1, "kind = \"rigid\""}}),
            "bad.toml:1:8: kind: expected \"rigid_body\", got \"rigid\"");
}

TEST(RigidBodyScenario, SyntaxErrorsNameFileLineAndColumn) {
  const std::string m = error_of({{9, "kp = = 5.0"}});
  EXPECT_TRUE(starts_with(m, "bad.toml:9:6: TOML syntax error: ")) << m;
}

TEST(RigidBodyScenario, OutputIntervalAndStepMustNotExceedTheDuration) {
  EXPECT_EQ(error_of({{14, "output_interval = 40"}}),
            "bad.toml:14:19: simulation.output_interval: must be <= duration (30), got 40");
  EXPECT_EQ(error_of({{16, "step = 31"}}),
            "bad.toml:16:8: simulation.step: must be <= duration (30), got 31");
  EXPECT_EQ(error_of({{13, "duration = 0.005"}, {14, ""}, {16, ""}}),
            "bad.toml:12:1: simulation.output_interval: the default must be <= duration (0.005), "
            "got 0.01; set output_interval explicitly");
}

TEST(RigidBodyScenario, IntegratorNameTypoIsSuggested) {
  EXPECT_EQ(error_of({{15, "integrator = \"rkmk_dp45\""}}),
            "bad.toml:15:14: simulation.integrator: must be one of \"rkmk4\", \"rkmk_dp54\", got "
            "\"rkmk_dp45\"; did you mean \"rkmk_dp54\"?");
}

// ---- example files ----------------------------------------------------------------------------

const std::filesystem::path kExamples = std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples";

TEST(ScenarioExamples, PdSlewExampleMatchesTheIssue) {
  const sim::RigidBodyScenario sc = parse_rigid_body(load_document(kExamples / "rigid_body_pd.toml"));
  EXPECT_EQ(sc.J, Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix());
  EXPECT_EQ(sc.R0_ib, lie::Mat3::Identity());
  EXPECT_EQ(sc.omega0_b, lie::Vec3(0.2, 0.3, 0.4));
  EXPECT_EQ(sc.law, sim::TorqueLaw::pd);
  EXPECT_EQ(sc.kp, 5.0);
  EXPECT_EQ(sc.kd, 1.0);
  EXPECT_LT((sc.R_ref_ib - lie::exp(lie::Vec3(0, std::numbers::pi / 2, 0))).norm(), 1e-15);
  EXPECT_EQ(sc.duration, 40.0);
  EXPECT_EQ(sc.output_interval, 0.05);
  EXPECT_EQ(sc.integrator.method, integrate::Method::rkmk4);
  EXPECT_EQ(sc.integrator.step, 0.01);
}

TEST(ScenarioExamples, FreeTumblingExampleUsesDormandPrince) {
  const sim::RigidBodyScenario sc = parse_rigid_body(load_document(kExamples / "rigid_body_free.toml"));
  EXPECT_EQ(sc.law, sim::TorqueLaw::free);
  EXPECT_EQ(sc.integrator.method, integrate::Method::rkmk_dp54);
  EXPECT_GT(sc.duration, 0.0);
}

TEST(ScenarioExamples, BadExamplesFailWithLocatedMessages) {
  const auto error_in = [](const char* name) {
    const std::filesystem::path path = kExamples / "bad" / name;
    return input_error([&] { (void)parse_rigid_body(load_document(path)); });
  };
  const std::string bad = (kExamples / "bad").string() + "/";
  EXPECT_TRUE(
      starts_with(error_in("typo_key.toml"),
                  bad + "typo_key.toml:15:1: control.kpp: unknown key 'kpp'; did you mean 'kp'?"));
  EXPECT_TRUE(
      starts_with(error_in("non_orthonormal.toml"),
                  bad + "non_orthonormal.toml:17:24: control.reference.matrix: not a rotation "
                        "matrix: ||R^T R - I||_F ="));
  EXPECT_EQ(error_in("nan_value.toml"),
            bad + "nan_value.toml:11:17: initial.omega_b[1]: must be finite, got nan");
}

}  // namespace
}  // namespace attiguard::scenario
