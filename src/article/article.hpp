// article.hpp (kutlog-article): the article's published results, and the computations that
// reproduce them from the reference (kutlog/reference.hpp). Used by kutlog-tables and tests.
//
// Zavalniuk, Romanyuk, Prozor, Snigur, "Energetically correct reflectance model based on the
// calculation of the angle between vectors", 2023, doi:10.31649/1999-9941-2023-56-1-75-82.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "kutlog/api.hpp"

KUTLOG_API_BEGIN
namespace kutlog::article {

// The row and column headings of Tables 1 and 2.
inline constexpr std::array<double, 9> kTableQ = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9};
inline constexpr std::array<int, 5> kTableK = {1, 2, 3, 4, 5};
// Both tables take their maximum over every integer n in [k + 1, kTableMaxN].
inline constexpr int kTableMaxN = 1000;

// A number as the article prints it: its value and half a unit of its last printed digit,
// so that a measurement m agrees with it at the printed precision iff |m - value| <= half_unit.
struct Printed {
  double value;
  double half_unit;
};
// `text` is the printed decimal ("27", "1.5"); the number is text * 10^-scale_digits (Table 2
// prints "42" meaning 42 * 10^-3). The value is the integer of the digits divided by a power of
// ten, both exact, in one correct rounding: the same double as the literal.
constexpr Printed parse_printed(std::string_view text, int scale_digits = 0) {
  long long digits = 0;
  int decimals = scale_digits;
  bool after_point = false;
  for (const char ch : text) {
    if (ch == '.') {
      after_point = true;
      continue;
    }
    digits = 10 * digits + (ch - '0');
    if (after_point) ++decimals;
  }
  double unit = 1;
  for (int i = 0; i < decimals; ++i) unit *= 10;
  return {double(digits) / unit, 0.5 / unit};
}

// Table 1: delta (%), the maximal relative error of F_kutlog against F_B in the epicenter zone,
// as printed (to one or two significant digits; the printed precision differs by cell).
inline constexpr std::string_view kTable1DeltaPercent[9][5] = {
    {"27", "15", "10", "7", "6"},         {"19", "10", "6", "5", "4"},
    {"13", "6", "4", "3", "2"},           {"8", "4", "2", "2", "1.5"},
    {"4", "2", "1.5", "1", "0.8"},        {"3", "1", "0.7", "0.5", "0.4"},
    {"5", "1.5", "0.8", "0.6", "0.5"},    {"7", "2.5", "1.5", "1", "0.9"},
    {"9.5", "3.5", "2.5", "1.7", "1.3"}};

// Table 2: Delta, the maximal |coef_fit * 2*pi*Int - 1|, as printed: in units of 1e-3
// ("42" is 42 * 10^-3, printed to that unit).
inline constexpr int kTable2ScaleDigits = 3;
inline constexpr std::string_view kTable2Delta[9][5] = {
    {"42", "49", "49", "43", "38"}, {"31", "21", "21", "21", "15"},
    {"47", "17", "10", "10", "10"}, {"67", "47", "38", "35", "30"},
    {"42", "16", "11", "11", "11"}, {"46", "23", "17", "13", "13"},
    {"65", "35", "24", "21", "16"}, {"78", "46", "35", "29", "23"},
    {"91", "60", "44", "33", "28"}};

inline constexpr Printed table1_printed(std::size_t row, std::size_t column) {
  return parse_printed(kTable1DeltaPercent[row][column]);
}
inline constexpr Printed table2_printed(std::size_t row, std::size_t column) {
  return parse_printed(kTable2Delta[row][column], kTable2ScaleDigits);
}

// Figure 4: the coef(n, k, Q) samples the fit was trained on, as printed (3 decimals, a
// trailing zero dropped). One entry is misprinted: Q = 0.5, k = 1, n = 2 is printed 0.699,
// while the integral gives 0.669 (a transposition of two digits).
struct CoefSample {
  double Q;
  int k;
  double n;
  double printed_coef;
  bool misprint;
};
inline constexpr CoefSample kFigure4[] = {
    {0.5, 1, 1, 0.477, false},     {0.5, 1, 2, 0.699, true},      {0.5, 1, 3, 0.88, false},
    {0.5, 1, 4, 1.095, false},     {0.5, 1, 5, 1.313, false},     {0.5, 1, 7, 1.75, false},
    {0.5, 1, 10, 2.41, false},     {0.5, 1, 20, 4.612, false},    {0.5, 1, 50, 11.227, false},
    {0.5, 1, 100, 22.255, false},  {0.5, 1, 200, 44.312, false},  {0.5, 1, 500, 110.482, false},
    {0.5, 1, 1000, 220.765, false}, {0.1, 1, 1, 0.477, false},    {0.1, 1, 2, 0.569, false},
    {0.1, 1, 5, 0.928, false},     {0.1, 1, 10, 1.57, false},     {0.1, 1, 20, 2.873, false},
    {0.1, 1, 50, 6.797, false},    {0.1, 1, 100, 13.344, false},  {0.1, 1, 200, 26.438, false},
    {0.1, 1, 500, 65.722, false},  {0.1, 1, 1000, 131.196, false}};
// Half a unit of the last printed digit.
inline constexpr double kFigure4PrintedHalfUnit = 0.0005;

// The epicenter zone of the highlight: the angles where F_B = cos^n(x) >= this. The article
// does not define it in its text; with 0.6 its Table 1 is reproduced (docs/article.md).
inline constexpr double kEpicenterFloor = 0.6;

// Table 1 recomputed: 100 * max over integer n in [k+1, 1000] of the relative error of
// F_kutlog against F_B in the epicenter zone.
double table1_delta_percent(double Q, int k);

// Table 2 recomputed: max over integer n in [k+1, 1000] of |coef * 2*pi*Int - 1|, with Int by
// quadrature (independent of the closed form behind coef_exact).
struct EnergyErrors {
  double fit;    // with the article's fitted coef
  double exact;  // with coef_exact
};
EnergyErrors table2_energy_errors(double Q, int k);

}  // namespace kutlog::article
KUTLOG_API_END
