#include "mpm/run/run_record.hpp"

#include <cstdint>

namespace mpm {

void RunRecord::save(StateArchive& archive) const {
  archive.put_number("run/initial_energy", initial_energy);
  const std::vector<std::int8_t> flags(warned.begin(), warned.end());
  archive.put_values<std::int8_t>("run/warned", flags);
  std::string text;
  for (const auto& w : warnings) text += w + '\n';
  archive.put_text("run/warnings", text);
}

void RunRecord::restore(const StateArchive& archive) {
  initial_energy = archive.number("run/initial_energy");
  const auto flags = archive.values<std::int8_t>("run/warned");
  if (flags.size() == warned.size()) warned.assign(flags.begin(), flags.end());
  const std::string text = archive.text("run/warnings");
  for (std::size_t begin = 0, end; (end = text.find('\n', begin)) != std::string::npos; begin = end + 1)
    warnings.push_back(text.substr(begin, end - begin));
}

}  // namespace mpm
