#pragma once

#include <gtest/gtest.h>

#include <string>

#include "registry.h"

namespace fooball::robustness {

/// Names a test instantiated over registeredBackends() after its backend, e.g. ".../box2d".
inline std::string backendTestName(const ::testing::TestParamInfo<BackendInfo>& param) {
  return std::string(param.param.name);
}

}  // namespace fooball::robustness
