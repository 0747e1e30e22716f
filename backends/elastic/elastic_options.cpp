#include "elastic_options.h"

namespace fooball::elastic {

std::vector<OptionSpec> elasticOptionSpecs() {
  const ElasticSettings defaults;
  return {
      {"substeps", "solver substeps per step (more: less overlap, less tunnelling)",
       static_cast<double>(defaults.substeps), 1, 1000, true, OptionRole::Substeps},
      {"threads", "worker threads per step, at most (results are identical for any count)",
       static_cast<double>(defaults.threads), 1, 64, true, OptionRole::Threads},
      {"balls_per_thread",
       "balls each worker thread needs before it joins a step (0: every thread, always)",
       static_cast<double>(defaults.ballsPerThread), 0, 1e9, true, OptionRole::BallsPerThread},
  };
}

ElasticSettings readElasticSettings(const OptionSet& options) {
  ElasticSettings settings;
  settings.substeps = static_cast<int>(options.value("substeps"));
  settings.threads = static_cast<int>(options.value("threads"));
  settings.ballsPerThread = static_cast<std::size_t>(options.value("balls_per_thread"));
  return settings;
}

}  // namespace fooball::elastic
