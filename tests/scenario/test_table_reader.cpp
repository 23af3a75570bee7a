#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "scenario/scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

using test::contains;
using test::input_error;
using test::starts_with;

TEST(TableReader, IntegersAreAcceptedAsNumbers) {
  const Document doc = parse_document("a = 3\nb = -2.5\n", "t.toml");
  const TableReader r(doc);
  EXPECT_EQ(r.number("a"), 3.0);
  EXPECT_EQ(r.number("b"), -2.5);
  EXPECT_EQ(r.number_or("c", 7.0), 7.0);
  r.finish();
}

TEST(TableReader, NanAndInfinityAreRejectedWithTheirPosition) {
  const Document doc = parse_document("a = nan\nb = -inf\nc = +inf\nv = [1, 2, nan]\n", "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("a"); }),
                          "t.toml:1:5: a: must be finite, got nan"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number_or("b", 0.0); }),
                          "t.toml:2:5: b: must be finite, got -inf"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("c", NumberRule::positive()); }),
                          "t.toml:3:5: c: must be finite, got inf"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.vector3("v"); }),
                          "t.toml:4:12: v[2]: must be finite, got nan"));
}

TEST(TableReader, NumberRulesAreEnforcedAndDescribed) {
  const Document doc = parse_document("neg = -1\nzero = 0\nbig = 2.5\n", "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("neg", NumberRule::positive()); }),
                          "t.toml:1:7: neg: must be > 0, got -1"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("zero", NumberRule::positive()); }),
                          "t.toml:2:8: zero: must be > 0, got 0"));
  EXPECT_EQ(r.number("zero", NumberRule::non_negative()), 0.0);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("neg", NumberRule::non_negative()); }),
                          "t.toml:1:7: neg: must be >= 0, got -1"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("big", NumberRule::range(0, 1)); }),
                          "t.toml:3:7: big: must be in [0, 1], got 2.5"));
  const NumberRule open{0.0, 1.0, true, true};
  EXPECT_TRUE(
      contains(input_error([&] { (void)r.number("zero", open); }), "must be in (0, 1), got 0"));
  EXPECT_TRUE(contains(input_error([&] { (void)r.vector("neg", NumberRule::positive()); }),
                       "expected a non-empty array of numbers > 0, got an integer"));
}

TEST(TableReader, WrongTypesNameWhatWasExpectedAndWhatWasFound) {
  const Document doc = parse_document(
      "s = \"5\"\nb = true\nt = { x = 1 }\nd = 2024-01-01\nf = 1.5\ni = 4\n", "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.number("s"); }),
                          "t.toml:1:5: s: expected a number, got a string \"5\""));
  EXPECT_TRUE(
      contains(input_error([&] { (void)r.number("b"); }), "expected a number, got a boolean"));
  EXPECT_TRUE(contains(input_error([&] { (void)r.vector3("t"); }),
                       "t: expected an array of 3 numbers, got a table"));
  EXPECT_TRUE(contains(input_error([&] { (void)r.number("d"); }), "got a date"));
  EXPECT_TRUE(
      contains(input_error([&] { (void)r.string("i"); }), "i: expected a string, got an integer"));
  EXPECT_TRUE(contains(input_error([&] { (void)r.integer("f", 0, 10); }),
                       "f: expected an integer, got a floating-point number"));
  EXPECT_TRUE(contains(input_error([&] { (void)r.boolean_or("i", false); }),
                       "expected a boolean (true or false), got an integer"));
  EXPECT_TRUE(
      contains(input_error([&] { (void)r.table("i"); }), "i: expected a table, got an integer"));
}

TEST(TableReader, IntegersBooleansAndStrings) {
  const Document doc = parse_document("n = 4\nflag = true\nmode = \"fast\"\n", "t.toml");
  const TableReader r(doc);
  EXPECT_EQ(r.integer("n", 1, 10), 4);
  EXPECT_EQ(r.integer_or("m", 2, 1, 10), 2);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.integer("n", 5, 10); }),
                          "t.toml:1:5: n: must be in [5, 10], got 4"));
  EXPECT_TRUE(r.boolean_or("flag", false));
  EXPECT_FALSE(r.boolean_or("other", false));
  static constexpr std::array<std::string_view, 2> modes{"fast", "slow"};
  EXPECT_EQ(r.string("mode", modes), "fast");
  EXPECT_EQ(r.string_or("label", "x"), "x");
  static constexpr std::array<std::string_view, 2> others{"fastest", "slow"};
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.string("mode", others); }),
                          "t.toml:3:8: mode: must be one of \"fastest\", \"slow\", got \"fast\"; "
                          "did you mean \"fastest\"?"));
  r.finish();
}

TEST(TableReader, ArrayShapesAreChecked) {
  const Document doc = parse_document(
      "two = [1, 2]\nempty = []\nnested = [[1, 2, 3], [4, 5, 6]]\nrow = [[1, 0, 0], [0, 1], [0, 0, "
      "1]]\n"
      "mixed = [1, \"a\", 3]\n",
      "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.vector3("two"); }),
                          "t.toml:1:7: two: expected an array of 3 numbers, got 2 elements"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.vector3("empty"); }),
                          "t.toml:2:9: empty: expected an array of 3 numbers, got an empty array"));
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.vector("empty"); }),
                  "t.toml:2:9: empty: expected a non-empty array of numbers, got an empty array"));
  EXPECT_TRUE(starts_with(
      input_error([&] { (void)r.matrix3("empty"); }),
      "t.toml:2:9: empty: expected an array of 3 rows of 3 numbers, got an empty array"));
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.matrix3("nested"); }),
                  "t.toml:3:10: nested: expected an array of 3 rows of 3 numbers, got 2 elements"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.matrix3("row"); }),
                          "t.toml:4:19: row[1]: expected a row of 3 numbers, got 2 elements"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.vector3("mixed"); }),
                          "t.toml:5:13: mixed[1]: expected a number, got a string \"a\""));
  EXPECT_EQ(r.vector("two").size(), 2);
}

TEST(TableReader, DirectionsAreNormalisedAndMustBeNonZero) {
  const Document doc = parse_document("d = [0, 3, 4]\nz = [0, 0, 0]\n", "t.toml");
  const TableReader r(doc);
  EXPECT_LT((r.direction("d") - Eigen::Vector3d(0, 0.6, 0.8)).norm(), 1e-15);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.direction("z"); }),
                          "t.toml:2:5: z: must be a non-zero direction, got [0, 0, 0]"));
}

TEST(TableReader, MissingKeysAreLocatedAtTheEnclosingTable) {
  const Document doc = parse_document("a = 1\n\n[sim]\nstep = 0.1\n", "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.table("sim").number("duration"); }),
                          "t.toml:3:1: sim.duration: missing required key (expected a number)"));
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.table("control"); }),
                  "t.toml:1:1: control: missing required key (expected a table [control])"));
  EXPECT_FALSE(r.optional_table("control").has_value());
}

TEST(TableReader, TypoOfARequiredKeyIsReportedAtTheTypo) {
  const Document doc = parse_document("[sim]\nduraton = 3\n", "t.toml");
  const TableReader sim = TableReader(doc).table("sim");
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)sim.number("duration"); }),
                  "t.toml:2:1: sim.duraton: unknown key 'duraton'; did you mean 'duration'? "
                  "(required key 'duration' is missing)"));
}

TEST(TableReader, FinishRejectsUnknownKeysListingTheKnownOnes) {
  const Document doc = parse_document(
      "kind = \"x\"\n[control]\nlaw = \"pd\"\nkp = 1\nkd = 2\nreference = { angle = 0 }\nkpp = 3\n",
      "bad.toml");
  const TableReader r(doc);
  (void)r.string("kind");
  const TableReader control = r.table("control");
  (void)control.string("law");
  (void)control.number("kp");
  (void)control.number("kd");
  (void)control.has("reference");
  EXPECT_EQ(
      input_error([&] { r.finish(); }),
      "bad.toml:7:1: control.kpp: unknown key 'kpp' (expected one of: kd, kp, law, reference); "
      "did you mean 'kp'?");
}

TEST(TableReader, FinishReportsTheFirstUnknownKeyOfTheFile) {
  const Document doc = parse_document(
      "a = 1\n[t]\nb = 2\nzz = 1\n[u]\nc = 3\n[[items]]\nw = 1\n[[items]]\nw = 2\nwx = 3\n",
      "t.toml");
  {
    const TableReader r(doc);
    (void)r.number("a");
    (void)r.table("t").number("b");
    (void)r.table("u").number("c");
    for (const TableReader& item : r.array_of_tables("items")) {
      (void)item.number("w");
    }
    EXPECT_TRUE(starts_with(input_error([&] { r.finish(); }),
                            "t.toml:4:1: t.zz: unknown key 'zz' (expected one of: b)"));
  }
  {
    const TableReader r(doc);
    (void)r.number("a");
    (void)r.table("t").has("zz");
    (void)r.table("t").number("b");
    (void)r.table("u").number("c");
    for (const TableReader& item : r.array_of_tables("items")) {
      (void)item.number("w");
    }
    EXPECT_TRUE(
        starts_with(input_error([&] { r.finish(); }),
                    "t.toml:11:1: items[1].wx: unknown key 'wx' (expected one of: w); did you "
                    "mean 'w'?"));
  }
  {
    const TableReader r(doc);
    (void)r.number("a");
    EXPECT_TRUE(starts_with(input_error([&] { r.finish(); }),
                            "t.toml:2:2: t: unknown key 't' (expected one of: a)"));
  }
}

TEST(TableReader, ArrayOfTablesMustBeNonEmptyTables) {
  const Document doc = parse_document("a = []\nb = [1]\nc = [{ x = 1 }, { x = 2 }]\n", "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(contains(input_error([&] { (void)r.array_of_tables("a"); }),
                       "a: expected a non-empty array of tables, got an empty array"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.array_of_tables("b"); }),
                          "t.toml:2:6: b[0]: expected a table, got an integer"));
  const auto items = r.array_of_tables("c");
  ASSERT_EQ(items.size(), 2U);
  EXPECT_EQ(items[1].key_path("x"), "c[1].x");
  EXPECT_TRUE(starts_with(input_error([&] { (void)items[1].number("x", NumberRule::range(5, 6)); }),
                          "t.toml:3:23: c[1].x: must be in [5, 6], got 2"));
}

TEST(TableReader, KeyPathsQuoteNonBareKeysAndFailHereLocatesTheTable) {
  const Document doc = parse_document("[\"odd key\"]\n\"a.b\" = 1\n", "t.toml");
  const TableReader r(doc);
  const TableReader odd = r.table("odd key");
  EXPECT_EQ(odd.key_path("a.b"), "\"odd key\".\"a.b\"");
  EXPECT_TRUE(
      starts_with(input_error([&] { odd.fail_here("wrong"); }), "t.toml:1:1: \"odd key\": wrong"));
  EXPECT_EQ(input_error([&] { r.fail_here("wrong"); }), "t.toml:1:1: wrong");
  EXPECT_EQ(input_error([&] { odd.fail("a.b", "bad"); }), "t.toml:2:9: \"odd key\".\"a.b\": bad");
}

// ---- rotations --------------------------------------------------------------------------------

TEST(TableReaderRotation, EveryFormGivesTheSameRotation) {
  const Document doc = parse_document(R"(
m = { matrix = [[0, 0, 1], [0, 1, 0], [-1, 0, 0]] }
q = { quaternion = [0.7071067811865476, 0, 0.7071067811865476, 0] }
a = { axis = [0, 2, 0], angle = 1.5707963267948966 }
d = { axis = [0, 1, 0], angle_deg = 90 }
v = { rotation_vector = [0, 1.5707963267948966, 0] }
)",
                                      "t.toml");
  const TableReader r(doc);
  const lie::Mat3 expected = lie::exp(lie::Vec3(0, std::numbers::pi / 2, 0));
  for (const char* key : {"m", "q", "a", "d", "v"}) {
    const lie::Mat3 R = r.rotation(key);
    EXPECT_LT((R - expected).norm(), 1e-15) << key;
    EXPECT_TRUE(lie::is_rotation(R)) << key;
  }
  r.finish();
}

TEST(TableReaderRotation, NonOrthonormalMatrixReportsTheMeasuredError) {
  const Document doc = parse_document(
      "r = { matrix = [[1, 0, 0], [0, 1, 0], [0, 0, 1.1]] }\n"
      "s = { matrix = [[1, 0, 0], [0, 1, 0], [0, 0, -1]] }\n",
      "t.toml");
  const TableReader r(doc);
  const std::string m = input_error([&] { (void)r.rotation("r"); });
  EXPECT_TRUE(
      starts_with(m, "t.toml:1:16: r.matrix: not a rotation matrix: ||R^T R - I||_F = 0.21"));
  EXPECT_TRUE(contains(m, "det = 1.1"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("s"); }),
                          "t.toml:2:16: s.matrix: not a rotation matrix: det = -1"));
}

TEST(TableReaderRotation, QuaternionMustBeUnitAndHaveFourComponents) {
  const Document doc = parse_document(
      "a = { quaternion = [1, 0.1, 0, 0] }\nb = { quaternion = [1, 0, 0] }\n"
      "c = { quaternion = [1, 0, 0, 1e-10] }\n",
      "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.rotation("a"); }),
                  "t.toml:1:20: a.quaternion: not a unit quaternion: norm = 1.00498756211208"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("b"); }),
                          "t.toml:2:20: b.quaternion: expected an array of 4 numbers [w, x, y, z] "
                          "(scalar first), got 3 elements"));
  EXPECT_TRUE(lie::is_rotation(r.rotation("c")));
}

TEST(TableReaderRotation, ExactlyOneFormIsRequired) {
  const Document doc = parse_document(
      "two = { quaternion = [1, 0, 0, 0], rotation_vector = [0, 0, 1] }\n"
      "none = {}\n"
      "typo = { quaternon = [1, 0, 0, 0] }\n"
      "both = { axis = [1, 0, 0], angle = 1, angle_deg = 57 }\n"
      "noangle = { axis = [1, 0, 0] }\n"
      "noaxis = { angle_deg = 30 }\n"
      "zero = { axis = [0, 0, 0], angle = 1 }\n"
      "notatable = [1, 0, 0, 0]\n",
      "t.toml");
  const TableReader r(doc);
  const std::string two = input_error([&] { (void)r.rotation("two"); });
  EXPECT_TRUE(starts_with(two,
                          "t.toml:1:7: two: 2 rotation forms given (quaternion and "
                          "rotation_vector): expected exactly one of: matrix"));
  EXPECT_TRUE(contains(two, "axis = [x, y, z] with angle (rad) or angle_deg"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("none"); }),
                          "t.toml:2:8: none: no rotation given: expected exactly one of: matrix"));
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.rotation("typo"); }),
                  "t.toml:3:10: typo.quaternon: unknown key 'quaternon' (expected one of: "
                  "angle, angle_deg, axis, matrix, quaternion, rotation_vector); did you mean "
                  "'quaternion'?"));
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.rotation("both"); }),
                  "t.toml:4:51: both.angle_deg: give either angle (rad) or angle_deg (deg)"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("noangle"); }),
                          "t.toml:5:11: noangle: axis needs an angle"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("noaxis"); }),
                          "t.toml:6:24: noaxis.angle_deg: an angle needs an axis"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("zero"); }),
                          "t.toml:7:17: zero.axis: must be a non-zero direction"));
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.rotation("notatable"); }),
                  "t.toml:8:13: notatable: expected a rotation table { ... } with exactly one "
                  "of"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.rotation("absent"); }),
                          "t.toml:1:1: absent: missing required key (expected a rotation table"));
}

// ---- inertia ----------------------------------------------------------------------------------

TEST(TableReaderInertia, PrincipalMomentsOrAFullMatrix) {
  const Document doc =
      parse_document("d = [1, 2, 3]\nm = [[2, 0.1, 0], [0.1, 2, 0], [0, 0, 3]]\n", "t.toml");
  const TableReader r(doc);
  EXPECT_EQ(r.inertia("d"), Eigen::Vector3d(1, 2, 3).asDiagonal().toDenseMatrix());
  EXPECT_DOUBLE_EQ(r.inertia("m")(0, 1), 0.1);
}

TEST(TableReaderInertia, NonPhysicalInertiaIsRejectedAtTheKey) {
  const Document doc = parse_document(
      "tri = [1, 1, 3]\nneg = [-1, 2, 2]\nasym = [[2, 1, 0], [0, 2, 0], [0, 0, 3]]\nshort = [1, "
      "2]\n"
      "word = \"big\"\nrows = [[1, 0, 0], [0, 1, 0]]\n",
      "t.toml");
  const TableReader r(doc);
  EXPECT_TRUE(
      starts_with(input_error([&] { (void)r.inertia("tri"); }),
                  "t.toml:1:7: tri: principal moments 1, 1, 3 violate the triangle inequality"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.inertia("neg"); }),
                          "t.toml:2:7: neg: inertia matrix is not positive definite"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.inertia("asym"); }),
                          "t.toml:3:8: asym: inertia matrix is not symmetric"));
  EXPECT_TRUE(starts_with(input_error([&] { (void)r.inertia("short"); }),
                          "t.toml:4:9: short: expected an array of 3 numbers, got 2 elements"));
  EXPECT_TRUE(
      contains(input_error([&] { (void)r.inertia("word"); }),
               "word: expected an inertia matrix [kg m^2]: principal moments [J1, J2, J3] or "
               "3 rows of 3 numbers, got a string \"big\""));
  EXPECT_TRUE(contains(input_error([&] { (void)r.inertia("rows"); }),
                       "rows: expected an array of 3 rows of 3 numbers, got 2 elements"));
}

// Components whose norm over- or underflows still name a direction (they used to be refused as
// "must be a non-zero direction").
TEST(TableReader, DirectionOfHugeOrTinyComponentsIsTheDirectionTheyName) {
  const Document doc =
      parse_document("a = [1e300, 1e300, 0]\nb = [1e-310, 0, 0]\nz = [0, 0, 0]\n", "t.toml");
  const TableReader r(doc);
  const Eigen::Vector3d a = r.direction("a");
  EXPECT_NEAR(a.x(), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(a.y(), std::sqrt(0.5), 1e-15);
  EXPECT_EQ(a.z(), 0.0);
  EXPECT_EQ(r.direction("b"), Eigen::Vector3d::UnitX());
  EXPECT_TRUE(contains(input_error([&] { (void)r.direction("z"); }), "must be a non-zero direction"));
}

// Inertias beyond any body are refused as input (J = 1e300 used to diverge in the first step).
TEST(TableReader, InertiaOutsideTheUsableRangeIsRefused) {
  const Document doc = parse_document(
      "big = [1e300, 1e300, 1e300]\nsmall = [1e-13, 1e-13, 1e-13]\nok = [1e-3, 1e3, 1e3]\n", "t.toml");
  const TableReader r(doc);
  EXPECT_EQ(input_error([&] { (void)r.inertia("big"); }),
            "t.toml:1:7: big: an entry of 1e+300 kg m^2 is beyond the usable range of inertias (at "
            "most 1e+12 kg m^2; is the unit kg m^2?)");
  EXPECT_TRUE(contains(input_error([&] { (void)r.inertia("small"); }),
                       "below the usable range of inertias (at least 1e-12 kg m^2"));
  EXPECT_EQ(r.inertia("ok")(1, 1), 1e3);
}

}  // namespace
}  // namespace attiguard::scenario
