// The workspace's programs (see program_index.h).
#include "lsp/program_index.h"

#include <mbc/addresses.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace mbc::lsp {

namespace {

/// The program a line starts: "O1234(...)", "O1234", ":1234", "<DRILL>".
std::optional<CalledProgram> programOfLine(std::string_view line) {
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) {
    line.remove_prefix(1);
  }
  if (line.empty()) {
    return std::nullopt;
  }
  if (line.front() == '<') {
    const std::size_t close = line.find('>');
    if (close == std::string_view::npos || close == 1) {
      return std::nullopt;
    }
    std::string name = "<";
    for (const char c : line.substr(1, close - 1)) {
      name.push_back(
          static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    }
    return CalledProgram{-1, name + ">"};
  }
  if (line.front() != 'O' && line.front() != 'o' && line.front() != ':') {
    return std::nullopt;
  }
  line.remove_prefix(1);
  long long number = 0;
  std::size_t digits = 0;
  while (digits < line.size() && digits < 9 &&
         std::isdigit(static_cast<unsigned char>(line[digits]))) {
    number = number * 10 + (line[digits] - '0');
    ++digits;
  }
  if (digits == 0 || number > kMaxCallNumber) {
    return std::nullopt;
  }
  const auto n = static_cast<int>(number);
  return CalledProgram{n, programName(n)};
}

bool skipped(const std::filesystem::path& dir) {
  const std::string name = dir.filename().string();
  return name.starts_with(".") || name == "build" || name == "node_modules";
}

} // namespace

void ProgramIndex::scanFile(const std::string& path) {
  // A file that says it is empty holds no program, and may be one that
  // blocks its reader (/proc/kmsg, under a workspace at /).
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size == 0 || size > kMaxFileBytes) {
    return;
  }
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int number = 0; std::getline(in, line); ++number) {
    if (const std::optional<CalledProgram> program = programOfLine(line)) {
      files_.try_emplace(*program, path, number);
    }
  }
}

void ProgramIndex::scan(const std::vector<std::string>& dirs) {
  for (const std::string& dir : dirs) {
    std::error_code error;
    std::filesystem::recursive_directory_iterator it(
        dir, std::filesystem::directory_options::skip_permission_denied, error);
    for (; !error && it != std::filesystem::recursive_directory_iterator();
         it.increment(error)) {
      if (scanned_ >= kMaxFiles) {
        return;
      }
      if (it->is_directory(error)) {
        if (skipped(it->path())) {
          it.disable_recursion_pending();
        }
        continue;
      }
      if (it->is_regular_file(error)) {
        ++scanned_;
        scanFile(it->path().string());
      }
    }
  }
}

void ProgramIndex::refresh(const std::string& path) {
  std::erase_if(files_,
                [&](const auto& entry) { return entry.second.first == path; });
  std::error_code error;
  if (std::filesystem::is_regular_file(path, error)) {
    scanFile(path);
  }
}

std::optional<std::string>
ProgramIndex::fileOf(const CalledProgram& program) const {
  const auto it = files_.find(program);
  if (it == files_.end()) {
    return std::nullopt;
  }
  return it->second.first;
}

std::vector<ProgramIndex::Entry>
ProgramIndex::matching(std::string_view query, std::size_t limit) const {
  const auto upper = [](std::string_view text) {
    std::string out(text);
    for (char& c : out) {
      c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    return out;
  };
  const std::string wanted = upper(query);
  std::vector<Entry> out;
  for (const auto& [program, where] : files_) {
    if (out.size() >= limit) {
      break;
    }
    if (upper(program.name).find(wanted) != std::string::npos) {
      out.push_back({program, where.first, where.second});
    }
  }
  return out;
}

} // namespace mbc::lsp
