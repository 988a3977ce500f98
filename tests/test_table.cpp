// The CSV quoting of tools/common/table.hpp, on the fields RFC 4180 singles out: the tools'
// own output has commas (tests/check_csv.py reads it back) but no quotes or line breaks yet.
#include <gtest/gtest.h>

#include "common/table.hpp"

namespace kutlog::tools {
namespace {

TEST(CsvField, PlainFieldsAreWrittenAsTheyAre) {
  EXPECT_EQ(csv_field("acos_u10"), "acos_u10");
  EXPECT_EQ(csv_field("x=1.18749082;y=500"), "x=1.18749082;y=500");
  EXPECT_EQ(csv_field(""), "");
}

TEST(CsvField, FieldsWithCommasQuotesOrLineBreaksAreQuoted) {
  EXPECT_EQ(csv_field("[-1, 1]"), "\"[-1, 1]\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_field("carriage\rreturn"), "\"carriage\rreturn\"");
}

}  // namespace
}  // namespace kutlog::tools
