#include "result_directory.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "deferred_signals.hpp"
#include "stale_temporaries.hpp"
#include "temporary_name.hpp"
#include "test_fault_points.hpp"

namespace stickslip::detail {

namespace fs = std::filesystem;

std::string ReadTextFile(const fs::path& path) {
  std::error_code ignored;
  std::ifstream in(path, std::ios::binary);
  if (!fs::is_regular_file(path, ignored) || !in) {
    throw InvalidInput::WithMessage(path.string(), fmt::format("cannot read '{}'", path.string()));
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

InvalidInput KeyError(const fs::path& file, const std::string& key, const std::string& what) {
  return InvalidInput::WithMessage(key, fmt::format("{}: key '{}' {}", file.string(), key, what));
}

nlohmann::ordered_json ParseJsonObject(const std::string& text, const fs::path& file) {
  using Json = nlohmann::ordered_json;
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::parse_error& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line L, column C: ...".
    const std::string what = e.what();
    const auto start = what.find("] ");
    throw InvalidInput::WithMessage(file.string(), fmt::format("{}: invalid JSON: {}", file.string(),
                                                               start == std::string::npos ? what : what.substr(start + 2)));
  }
  if (!json.is_object()) {
    throw InvalidInput::WithMessage(file.string(), fmt::format("{}: is invalid: valid a JSON object", file.string()));
  }
  return json;
}

bool IsNumberedName(std::string_view name, std::string_view prefix, bool labelled) {
  if (!name.starts_with(prefix)) return false;
  std::string_view rest = name.substr(prefix.size());
  const auto span = [&rest](auto is) {
    const std::size_t n = std::find_if_not(rest.begin(), rest.end(), is) - rest.begin();
    rest.remove_prefix(n);
    return n;
  };
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  const std::size_t number = span(digit);
  if (number == 0 || number > 9) return false;
  if (rest.empty()) return true;
  if (!labelled || rest.front() != '-') return false;
  rest.remove_prefix(1);
  return span([](char c) { return c >= 'A' && c <= 'Z'; }) > 0 && span(digit) > 0 && rest.empty();
}

bool IsRunEntry(const fs::path& relative) {
  return std::distance(relative.begin(), relative.end()) == 1 && IsRunFileName(relative.filename().string());
}

OwnedEntry EntriesWithRuns(OwnedName own_file, OwnedName own_run) {
  return [own_file = std::move(own_file), own_run = std::move(own_run)](const fs::path& relative) {
    const std::string top = relative.begin()->string();
    const bool run = own_run(top);
    switch (std::distance(relative.begin(), relative.end())) {
      case 1: return own_file(top) || run;
      case 2: return run && IsRunFileName(relative.filename().string());
      default: return false;
    }
  };
}

namespace {

std::set<std::string> ValuesOf(const nlohmann::ordered_json& json, const std::vector<std::string>& keys) {
  std::set<std::string> found;
  if (json.is_array()) {
    for (const auto& element : json) found.merge(ValuesOf(element, keys));
  } else if (json.is_object()) {
    for (const auto& [key, value] : json.items()) {
      if (value.is_string() && std::find(keys.begin(), keys.end(), key) != keys.end()) found.insert(value.get<std::string>());
      found.merge(ValuesOf(value, keys));
    }
  }
  return found;
}

}  // namespace

std::set<std::string> ListedNames(const fs::path& index, const std::vector<std::string>& keys) {
  std::error_code ignored;
  if (!fs::is_regular_file(index, ignored)) return {};
  try {
    return ValuesOf(ParseJsonObject(ReadTextFile(index), index), keys);
  } catch (const InvalidInput&) {
    return {};  // a damaged index lists nothing: every numbered entry is then the user's, and kept
  }
}

namespace {

// The entries below root/relative that are not ours, at every depth: a directory of ours (not a
// link) is looked into, one of the user's is taken whole. A symbolic link is the user's whatever
// its name: no writer makes one. Listed before anything moves: POSIX leaves open what a listing
// shows of entries moved during it.
std::vector<fs::path> OthersIn(const fs::path& root, const fs::path& relative, const OwnedEntry& ours) {
  std::vector<fs::path> others;
  for (const fs::directory_entry& entry : fs::directory_iterator(root / relative)) {
    const fs::path name = relative / entry.path().filename();
    if (!ours(name) || entry.is_symlink()) {
      others.push_back(name);
    } else if (entry.is_directory() && !entry.is_symlink()) {
      const std::vector<fs::path> deeper = OthersIn(root, name, ours);
      others.insert(others.end(), deeper.begin(), deeper.end());
    }
  }
  return others;
}

// Moves root/relative to into/relative, creating the directories of ours it lies in (a branch the
// new write no longer has keeps the user's files in it). Never over an entry: the writer's own
// never has the user's names.
void MoveEntry(const fs::path& root, const fs::path& into, const fs::path& relative) {
  fs::create_directories(into / relative.parent_path());
  if (fs::exists(fs::symlink_status(into / relative))) {
    throw std::runtime_error(
        fmt::format("cannot keep '{}': the new output has an entry of that name", (root / relative).string()));
  }
  fs::rename(root / relative, into / relative);
}

// Removes the entries of ours below root/relative, and the directories of ours that then are
// empty; the user's stay.
void RemoveOurs(const fs::path& root, const fs::path& relative, const OwnedEntry& ours) {
  std::error_code ignored;
  std::vector<fs::directory_entry> entries;
  for (const fs::directory_entry& entry : fs::directory_iterator(root / relative, ignored)) entries.push_back(entry);
  for (const fs::directory_entry& entry : entries) {
    const fs::path name = relative / entry.path().filename();
    if (!ours(name)) continue;
    if (entry.is_directory(ignored) && !entry.is_symlink(ignored)) RemoveOurs(root, name, ours);
    fs::remove(root / name, ignored);  // a directory that still holds the user's files stays
  }
}

std::vector<std::string> SortedNames(const std::vector<fs::path>& entries) {
  std::vector<std::string> names;
  for (const fs::path& entry : entries) names.push_back(entry.generic_string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

std::vector<std::string> ReplaceDirectory(const fs::path& results_root, const std::string& output,
                                          const std::function<void(const fs::path&)>& write, const OwnedEntry& ours,
                                          const OwnedEntry& ours_before) {
  fs::create_directories(results_root);
  RemoveStaleTemporaries(results_root, output, ours);
  // Destroyed last: a signal during the write ends in the catch below, then the process ends by it.
  const DeferredSignals signals;
  const fs::path target = results_root / output;
  const fs::path temporary = results_root / TemporaryName(output, "tmp");
  const fs::path old = results_root / TemporaryName(output, "old");
  if (!fs::create_directory(temporary)) {
    throw std::runtime_error(fmt::format("cannot write '{}': '{}' is in the way", target.string(), temporary.string()));
  }
  std::vector<fs::path> kept;
  std::error_code ignored;
  try {
    write(temporary);
    if (signals.Outermost()) PauseBeforeRenameForTests();
    DeferredSignals::ThrowIfPending();
    if (fs::exists(target)) {
      for (const fs::path& entry : OthersIn(target, {}, ours_before)) {
        MoveEntry(target, temporary, entry);
        kept.push_back(entry);
      }
      fs::rename(target, old);
    }
    fs::rename(temporary, target);
  } catch (...) {
    if (!fs::exists(target) && fs::exists(old)) fs::rename(old, target, ignored);
    for (const fs::path& entry : kept) fs::rename(temporary / entry, target / entry, ignored);
    // Not remove_all of the whole: a file of the user's that could not be moved back stays.
    RemoveOurs(temporary, {}, ours);
    fs::remove(temporary, ignored);
    throw;
  }
  fs::remove_all(old, ignored);
  return SortedNames(kept);
}

}  // namespace stickslip::detail
