#pragma once

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace fooball::testing {

/// Records a measured number as a property of the running test (in --gtest_output=xml), to
/// three significant digits: the agreement tables of docs/accuracy.md come from these.
inline void recordMeasurement(const std::string& key, double value) {
  std::ostringstream text;
  text.precision(3);
  text << value;
  ::testing::Test::RecordProperty(key, text.str());
}

}  // namespace fooball::testing
