// io/json_values: vectors and matrices as JSON arrays.

#include <gtest/gtest.h>

#include <vector>

#include <Eigen/Core>

#include "attiguard/io/json_values.hpp"

namespace attiguard::io {
namespace {

TEST(JsonValues, AVectorIsAnArrayOfItsElementsInOrder) {
  EXPECT_EQ(json_array(std::vector<double>{1.5, -2.0, 3.25}).dump(), "[1.5,-2.0,3.25]");
  EXPECT_EQ(json_array(Eigen::Vector3d(0.1, 0.2, 0.3)).dump(), "[0.1,0.2,0.3]");
  EXPECT_EQ(json_array(std::vector<double>{}).dump(), "[]");
}

TEST(JsonValues, EachElementGoesThroughTheMap) {
  const auto doubled = [](double x) { return 2.0 * x; };
  EXPECT_EQ(json_array(std::vector<double>{1.0, 4.0}, doubled).dump(), "[2.0,8.0]");
}

TEST(JsonValues, AMatrixIsAnArrayOfItsRows) {
  Eigen::Matrix3d M;
  M << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  EXPECT_EQ(json_rows(M).dump(), "[[1.0,2.0,3.0],[4.0,5.0,6.0],[7.0,8.0,9.0]]");
  const Eigen::Matrix<double, 2, 3> W = M.topRows<2>();
  EXPECT_EQ(json_rows(W).dump(), "[[1.0,2.0,3.0],[4.0,5.0,6.0]]");
}

}  // namespace
}  // namespace attiguard::io
