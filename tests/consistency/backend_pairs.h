#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "backend_profiles.h"
#include "fooball/run_spec.h"
#include "registry.h"

namespace fooball::testing {

/// Two registered backends that run the same scene.
struct BackendPair {
  BackendInfo first;
  BackendInfo second;
};

/// Every unordered pair of registered backends, in registry order: a new backend is compared
/// with all the others by its registry line alone.
inline std::vector<BackendPair> everyBackendPair() {
  const auto backends = registeredBackends();
  std::vector<BackendPair> pairs;
  for (std::size_t i = 0; i < backends.size(); ++i) {
    for (std::size_t j = i + 1; j < backends.size(); ++j)
      pairs.push_back({backends[i], backends[j]});
  }
  return pairs;
}

/// A new `info` backend with the options its row in tests/backend_profiles.cpp gives this suite
/// (BackendProfile::consistencyOptions).
inline std::unique_ptr<Backend> createForConsistency(const BackendInfo& info) {
  return createWithOptions(info.name, profileFor(info.name).consistencyOptions);
}

/// "elastic_vs_box2d".
inline std::string pairName(const ::testing::TestParamInfo<BackendPair>& info) {
  return std::string(info.param.first.name) + "_vs_" + std::string(info.param.second.name);
}

}  // namespace fooball::testing
