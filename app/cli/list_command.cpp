#include "list_command.h"

#include <algorithm>
#include <string>

#include "fooball/number_text.h"
#include "fooball/presets.h"
#include "registry.h"
#include "run_options.h"
#include "text_table.h"

namespace fooball::cli {

namespace {

std::string rangeText(const OptionSpec& spec) {
  if (!spec.choices.empty()) {
    std::string names;
    for (const std::string& choice : spec.choices)
      names += (names.empty() ? "" : ", ") + choice;
    return "one of " + names;
  }
  return std::string(spec.integer ? "integer" : "number") + " in [" + exactNumberText(spec.min) +
         ", " + exactNumberText(spec.max) + "]";
}

void printBackends(std::ostream& out) {
  out << "Backends (--backend NAME, default " << kDefaultBackend
      << "; set options with --option KEY=VALUE):\n";
  // One table for all backends, so the option columns line up across them.
  std::size_t nameWidth = 0;
  for (const BackendInfo& info : registeredBackends()) {
    nameWidth = std::max(nameWidth, info.name.size());
  }
  TextTable table;
  for (const BackendInfo& info : registeredBackends()) {
    std::string heading = "  " + std::string(info.name);
    heading.append(nameWidth - info.name.size() + 2, ' ');
    table.addLine("");
    table.addLine(heading + std::string(info.description));
    if (const std::string reason = unavailableReason(info); !reason.empty())
      table.addLine("      unavailable here: " + reason);
    const auto backend = info.create();
    const auto specs = backend->options().specs();
    if (specs.empty()) table.addLine("      (no options)");
    for (const OptionSpec& spec : specs) {
      const std::string defaultText =
          spec.choices.empty() ? exactNumberText(spec.defaultValue)
                               : spec.choices[static_cast<std::size_t>(spec.defaultValue)];
      table.addRow({spec.name, "default " + defaultText, rangeText(spec), spec.description});
    }
  }
  table.print(out, 6);
}

void printPresets(std::ostream& out) {
  out << "Presets (--preset NAME, default " << kDefaultPreset << "):\n";
  TextTable table;
  for (const Preset& preset : presets()) {
    table.addRow({std::string(preset.name), std::string(preset.description)});
  }
  table.print(out, 2);
}

}  // namespace

void printList(std::ostream& out) {
  printBackends(out);
  out << '\n';
  printPresets(out);
}

}  // namespace fooball::cli
