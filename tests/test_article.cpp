// The article's published tables, reproduced from the reference cell by cell.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "kutlog/article.hpp"
#include "kutlog/reference.hpp"

namespace kutlog::article {
namespace {

struct Cell {
  std::size_t row, column;
};
std::vector<Cell> all_cells() {
  std::vector<Cell> cells;
  for (std::size_t row = 0; row < kTableQ.size(); ++row)
    for (std::size_t column = 0; column < kTableK.size(); ++column) cells.push_back({row, column});
  return cells;
}
std::string cell_name(const testing::TestParamInfo<Cell>& info) {
  char name[32];
  std::snprintf(name, sizeof name, "Q0_%d_k%d", int(std::lround(kTableQ[info.param.row] * 10)),
                kTableK[info.param.column]);
  return name;
}

class Table1 : public testing::TestWithParam<Cell> {};
TEST_P(Table1, DeltaReproducedWithinTheStatedTolerance) {
  const auto [row, column] = GetParam();
  const int k = kTableK[column];
  const double ours = table1_delta_percent(kTableQ[row], k);
  const double printed = kTable1DeltaPercent[row][column];
  // One cell misses the 0.7 tolerance by 0.02: Q = 0.1, k = 4 is 7.72 % (at n = 1000, at the
  // edge of the zone), printed as 7, i.e. cut to one digit. Asserted as exactly that.
  if (kTableQ[row] == 0.1 && k == 4) {
    EXPECT_NEAR(ours, 7.72, 0.005);
    EXPECT_EQ(std::floor(ours), printed);
    return;
  }
  // Published to one or two digits, with an epicenter zone the text leaves undefined.
  const double tolerance_points = k == 1 ? 2.0 : 0.7;
  EXPECT_NEAR(ours, printed, tolerance_points);
}
INSTANTIATE_TEST_SUITE_P(Cell, Table1, testing::ValuesIn(all_cells()), cell_name);

class Table2 : public testing::TestWithParam<Cell> {};
TEST_P(Table2, FittedCoefEnergyErrorReproducedAndExactCoefExact) {
  const auto [row, column] = GetParam();
  const EnergyErrors errors = table2_energy_errors(kTableQ[row], kTableK[column]);
  EXPECT_NEAR(errors.fit, kTable2Delta[row][column], 5e-3);
  EXPECT_LT(errors.exact, 1e-12);
}
INSTANTIATE_TEST_SUITE_P(Cell, Table2, testing::ValuesIn(all_cells()), cell_name);

TEST(Figure4, EverySampleToItsPrintedDigitsExceptTheMisprint) {
  for (const CoefSample& sample : kFigure4) {
    const double ours = ref::coef_exact(sample.n, sample.k, sample.Q);
    SCOPED_TRACE("Q=" + std::to_string(sample.Q) + " n=" + std::to_string(sample.n));
    if (sample.misprint) {
      EXPECT_GT(std::fabs(ours - sample.printed_coef), 0.01);
      EXPECT_NEAR(ours, 0.669, kFigure4PrintedHalfUnit);  // 0.699 with two digits swapped
    } else {
      EXPECT_NEAR(ours, sample.printed_coef, kFigure4PrintedHalfUnit);
    }
  }
}

TEST(Article, MaximalFittedEnergyErrorIs0_091) {
  EXPECT_NEAR(table2_energy_errors(0.9, 1).fit, 0.091, 1e-3);
}

}  // namespace
}  // namespace kutlog::article
