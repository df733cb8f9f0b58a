#include "result_directory.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

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

std::vector<std::string> ReplaceDirectory(const fs::path& results_root, const std::string& output,
                                          const std::function<void(const fs::path&)>& write,
                                          const std::function<bool(const std::string&)>& ours) {
  fs::create_directories(results_root);
  const fs::path target = results_root / output;
  const fs::path temporary = results_root / fmt::format(".{}.tmp.{}", output, static_cast<long>(::getpid()));
  const fs::path old = results_root / fmt::format(".{}.old.{}", output, static_cast<long>(::getpid()));
  std::error_code ignored;
  fs::remove_all(temporary, ignored);
  fs::create_directories(temporary);
  std::vector<std::string> kept;
  try {
    write(temporary);
    if (fs::exists(target)) {
      // Listed first: POSIX leaves open what a directory listing shows of entries moved during it.
      std::vector<std::string> others;
      for (const fs::directory_entry& entry : fs::directory_iterator(target)) {
        const std::string name = entry.path().filename().string();
        if (!ours(name)) others.push_back(name);
      }
      for (const std::string& name : others) {
        fs::rename(target / name, temporary / name);
        kept.push_back(name);
      }
      fs::rename(target, old);
    }
    fs::rename(temporary, target);
  } catch (...) {
    if (!fs::exists(target) && fs::exists(old)) fs::rename(old, target, ignored);
    for (const std::string& name : kept) fs::rename(temporary / name, target / name, ignored);
    // Not remove_all of the whole: a file of the user's that could not be moved back stays.
    std::vector<fs::path> written;
    for (const fs::directory_entry& entry : fs::directory_iterator(temporary, ignored)) {
      if (ours(entry.path().filename().string())) written.push_back(entry.path());
    }
    for (const fs::path& p : written) fs::remove_all(p, ignored);
    fs::remove(temporary, ignored);
    throw;
  }
  fs::remove_all(old, ignored);
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace stickslip::detail
