#include "driver/batch_outputs.h"

#include <mbc/read_file.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

namespace mbc::driver {

namespace {

namespace fs = std::filesystem;

struct Listed {
  std::string id;
  int line = 0;
  std::string status;
  std::string text; // the whole line, with its '\n'
};

// The whole lines of a results file: a line cut by a crash is not one.
std::vector<std::string> wholeLines(const std::string& path) {
  std::string content;
  std::vector<std::string> lines;
  if (readFile(path, content) != 0) {
    return lines;
  }
  for (std::size_t at = 0, end;
       (end = content.find('\n', at)) != std::string::npos; at = end + 1) {
    lines.push_back(content.substr(at, end - at + 1));
  }
  return lines;
}

// results.csv: "id,line,status,...", a header first.
std::vector<Listed> listedInCsv(const std::string& path) {
  std::vector<Listed> out;
  const std::vector<std::string> lines = wholeLines(path);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream fields(lines[i]);
    Listed l;
    std::string line;
    if (std::getline(fields, l.id, ',') && std::getline(fields, line, ',') &&
        std::getline(fields, l.status, ',')) {
      l.line = std::atoi(line.c_str());
      l.text = lines[i];
      out.push_back(std::move(l));
    }
  }
  return out;
}

// batch.jsonl: an object per row with "id", "line" and "status" (earlier
// versions named the id "row": a batch one of them began resumes too).
std::vector<Listed> listedInJsonl(const std::string& path) {
  std::vector<Listed> out;
  for (const std::string& text : wholeLines(path)) {
    const nlohmann::json row = nlohmann::json::parse(text, nullptr, false);
    if (!row.is_object()) {
      continue;
    }
    const nlohmann::json id =
        row.value("id", row.value("row", nlohmann::json()));
    if (id.is_string() &&
        row.value("line", nlohmann::json()).is_number_integer() &&
        row.value("status", nlohmann::json()).is_string()) {
      out.push_back({id.get<std::string>(), row["line"].get<int>(),
                     row["status"].get<std::string>(), text});
    }
  }
  return out;
}

std::vector<Listed> listedIn(const std::string& path) {
  return path.ends_with(".jsonl") ? listedInJsonl(path) : listedInCsv(path);
}

// How many rows lead `rows` finished in `listed`.
std::size_t finishedPrefix(const std::vector<BatchRow>& rows,
                           const std::vector<Listed>& listed) {
  std::size_t n = 0;
  while (n < rows.size() && n < listed.size() && listed[n].id == rows[n].id &&
         listed[n].line == rows[n].line &&
         (listed[n].status == "ended" || listed[n].status == "alarm")) {
    ++n;
  }
  return n;
}

// "-of-4" for the files of --shard I/4, "" for a whole batch's.
std::string shardingOf(const std::string& name) {
  const std::size_t of = name.find(".shard-");
  if (of == std::string::npos) {
    return "";
  }
  const std::size_t n = name.find("-of-", of);
  return n == std::string::npos ? "" : name.substr(n, name.find('.', n) - n);
}

bool isResultsFile(const std::string& name) {
  return (name.starts_with("results") && name.ends_with(".csv")) ||
         (name.starts_with("batch") && name.ends_with(".jsonl"));
}

} // namespace

FinishedRows finishedRows(const std::vector<BatchRow>& rows,
                          const std::string& resultsPath,
                          const std::string& combinedPath) {
  const std::vector<Listed> results = listedIn(resultsPath);
  std::size_t count = finishedPrefix(rows, results);
  std::vector<Listed> combined;
  if (!combinedPath.empty()) {
    combined = listedIn(combinedPath);
    count = std::min(count, finishedPrefix(rows, combined));
  }
  FinishedRows out;
  out.count = count;
  for (std::size_t i = 0; i < count; ++i) {
    out.alarms += results[i].status == "alarm";
    out.results += results[i].text;
    out.combined += combinedPath.empty() ? "" : combined[i].text;
  }
  return out;
}

void removeStaleOutputs(const std::string& dir,
                        const std::vector<BatchRow>& table,
                        const std::vector<BatchRow>& mine, std::size_t keep,
                        const std::string& resultsName,
                        const std::string& combinedName, bool combined) {
  std::set<std::string> others, kept;
  for (const BatchRow& row : table) {
    others.insert(row.id);
  }
  for (std::size_t i = 0; i < mine.size(); ++i) {
    others.erase(mine[i].id);
    if (i < keep) {
      kept.insert(mine[i].id);
    }
  }
  std::error_code ec;
  std::vector<std::string> stale;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!isResultsFile(name)) {
      continue;
    }
    for (const Listed& l : listedIn(entry.path().string())) {
      // Another shard's rows are its to write.
      if (!others.contains(l.id) && !kept.contains(l.id)) {
        for (const char* ext : kRowFileExtensions) {
          fs::remove(fs::path(dir) / (l.id + ext), ec);
        }
      }
    }
    // The results files of another sharding or of the other mode; those of
    // the other shards of this sharding are theirs.
    const bool written =
        name == resultsName || (combined && name == combinedName);
    const bool ours = name == resultsName || name == combinedName;
    if (!written && (ours || shardingOf(name) != shardingOf(resultsName))) {
      stale.push_back(name);
    }
  }
  for (const std::string& name : stale) {
    fs::remove(fs::path(dir) / name, ec);
  }
}

} // namespace mbc::driver
