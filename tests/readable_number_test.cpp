#include "readable_number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fooball::text {
namespace {

TEST(ReadableNumber, SignificantDigitsAsAsked) {
  EXPECT_EQ(readableText(1.0 / 60.0), "0.0166667");
  EXPECT_EQ(readableText(1.0 / 60.0, 3), "0.0167");
  EXPECT_EQ(readableText(1234567.0, 2), "1.2e+06");
  EXPECT_EQ(readableText(-0.5), "-0.5");
}

TEST(ReadableNumber, FiguresHaveFourSignificantDigits) {
  EXPECT_EQ(figureText(0.0), "0");
  EXPECT_EQ(figureText(0.012345), "0.01235");  // %g rounds half to even on the binary value
  EXPECT_EQ(figureText(1234.0), "1234");
  EXPECT_EQ(figureText(99999.0), "1e+05");
  EXPECT_EQ(figureText(-2.5), "-2.5");
}

TEST(ReadableNumber, VerySmallOrLargeFiguresInExponentFormWithThreeDigits) {
  EXPECT_EQ(figureText(1.2345e-5), "1.23e-05");
  EXPECT_EQ(figureText(-0.000999), "-9.99e-04");
  EXPECT_EQ(figureText(0.001), "0.001");
  EXPECT_EQ(figureText(2.5e6), "2.50e+06");
  EXPECT_EQ(figureText(1e5), "1.00e+05");
}

TEST(ReadableNumber, NoFigureForNoValue) {
  EXPECT_EQ(figureText(std::nan("")), "—");
  EXPECT_EQ(figureText(std::numeric_limits<double>::infinity()), "—");
  EXPECT_EQ(figureText(-std::numeric_limits<double>::infinity()), "—");
}

}  // namespace
}  // namespace fooball::text
