// What an earlier batch left in --out: the rows it finished, which
// --resume keeps, and the files of rows this batch will not write over,
// which are removed so that they never mix with this batch's results.
#pragma once

#include "driver/batch_table.h"

#include <array>
#include <string>
#include <vector>

namespace mbc::driver {

/// A row's files under --out: ID plus each of these.
inline constexpr std::array<const char*, 4> kRowFileExtensions = {
    ".toolpath.jsonl", ".dprnt", ".vars.json", ".log"};

/// The lines an earlier batch wrote for the rows it finished, in the
/// results files of this shard.
struct FinishedRows {
  std::size_t count = 0;         // how many of `rows` lead, finished
  std::size_t alarms = 0;        // how many of them stopped by an alarm
  std::string results, combined; // their lines of results.csv, batch.jsonl
};

/// The rows at the head of `rows` (this shard's, in table order) that the
/// results file `resultsPath` (and `combinedPath` when not empty) of an
/// earlier batch of the same table lists as ended or stopped by an alarm.
/// Rows are written to those files in table order, so the finished ones
/// are a prefix; an interrupted or unwritten row ends it.
FinishedRows finishedRows(const std::vector<BatchRow>& rows,
                          const std::string& resultsPath,
                          const std::string& combinedPath);

/// Removes from `dir` what earlier batches wrote that this one (`shard` of
/// `table`, whose own rows are `mine`; `keep` of them finished and kept)
/// will not write: the files of rows no longer in the table or of this
/// shard's rows that run again, and results files of other shardings.
/// Only rows that earlier results files list are touched, never other
/// files of the folder.
void removeStaleOutputs(const std::string& dir,
                        const std::vector<BatchRow>& table,
                        const std::vector<BatchRow>& mine, std::size_t keep,
                        const std::string& resultsName,
                        const std::string& combinedName, bool combined);

} // namespace mbc::driver
