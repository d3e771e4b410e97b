// The motions' outputs made on a thread of their own while the run goes on
// (`mbc run --toolpath FILE`, `--svg`, `--html` where a second core is
// free): the run's thread copies motions into chunks of a ring, the writer
// formats the JSONL records and writes them, and draws the drawing and the
// page, in order. The run counts an upper bound of what each motion adds
// against the output limit; when the bounds pass the limit the runtime asks
// for the exact count (settle), so --max-output stops the run at the same
// block as when the run makes the outputs itself.
#pragma once

#include <mbc/runtime.h>

#include <array>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include "runner/html_writer.h"
#include "runner/output_files.h"
#include "runner/run_options.h"
#include "runner/svg_writer.h"

namespace mbc::runner {

/// Where a motion goes: the JSONL toolpath file, the drawing, the page
/// (each may be absent).
struct MotionTargets {
  OutputFile* toolpath = nullptr;
  SvgWriter* svg = nullptr;
  HtmlWriter* html = nullptr;

  bool any() const {
    return toolpath != nullptr || svg != nullptr || html != nullptr;
  }

  /// Writes the motion to each target; the bytes they grew by.
  std::size_t take(const mbrt_motion& motion) const;

  /// The most bytes take() may return for `motion`.
  std::size_t bound(const mbrt_motion& motion) const;

  /// These targets without those `taken` has.
  MotionTargets except(const MotionTargets& taken) const;
};

class ToolpathThread {
public:
  /// Starts the writer on `targets`, which only it touches until finish().
  explicit ToolpathThread(const MotionTargets& targets);
  ~ToolpathThread();

  ToolpathThread(const ToolpathThread&) = delete;
  ToolpathThread& operator=(const ToolpathThread&) = delete;

  /// On the run's thread: a motion to write, and the bytes to count for it
  /// (at least its record's).
  std::size_t push(const mbrt_motion& motion);

  /// Waits until every motion pushed is written; how many of the bytes
  /// push() counted since the last settle were over the exact ones.
  std::uint64_t settle();

  /// Writes what is left and stops the writer (once; the destructor too).
  void finish();

  /// Which of `outputs` are made on a thread of their own, as `choice`
  /// asks; automatically, when the process may run on a second core: the
  /// drawings, and the toolpath when it is a file that is not standard
  /// output (DPRNT shares it, in order) nor a terminal.
  static MotionTargets wanted(WriterThread choice,
                              const MotionTargets& outputs);

  /// What `--time` says the thread made: "the toolpath", "the SVG"...
  std::string madeText() const;

private:
  // Motions go over a chunk at a time, and the writer is woken (a system
  // call each time) only when a batch of chunks waits for it: waking it per
  // chunk cost the run more than formatting the records did.
  static constexpr std::size_t kChunk = 256;
  static constexpr std::uint64_t kRing = 32;       // chunks
  static constexpr std::uint64_t kWakeBatch = 8;   // chunks
  static constexpr std::uint64_t kRoomToWake = 16; // chunks free

  /// A motion as the writer needs it: the fields a record prints, and the
  /// drawings' when there are any, copied (a slot is not cleared first;
  /// the rest is never read).
  struct Slot {
    mbrt_motion motion;

    Slot() {} // NOLINT: left uninitialised on purpose
  };

  struct Chunk {
    std::size_t size; // set when published
    std::array<Slot, kChunk> slots;
  };

  static unsigned usableCores();
  /// Publishes the chunk being filled, if it holds any motion.
  void publish();
  /// Waits until the writer has written the chunks before `chunk`.
  void waitForWriter(std::uint64_t chunk);
  void wakeWriter();
  void write();
  /// A motion's program or file name, kept (`last`: the last one kept for
  /// that field): the runtime's text changes from block to block, and the
  /// writer reads it later.
  const char* kept(const char* name, const char*& last);

  const MotionTargets targets_;
  const bool drawing_; // the slots carry what the drawings read
  std::unique_ptr<Chunk[]> ring_;

  // The run's thread only.
  std::uint64_t filling_ = 0; // chunk, counted from the first
  std::size_t count_ = 0;     // motions in it
  std::uint64_t bounded_ = 0;
  std::set<std::string> names_; // the writer reads the strings only
  const char* lastProgram_ = nullptr;
  const char* lastFile_ = nullptr;
  std::uint64_t settledBounds_ = 0;
  std::uint64_t settledExact_ = 0;

  // Chunks published by the run and written by the writer, and the bytes
  // written (read once the writer has caught up).
  std::atomic<std::uint64_t> published_{0};
  std::atomic<std::uint64_t> written_{0};
  std::atomic<std::uint64_t> exact_{0};

  // Sleeping: each side says it sleeps, then looks once more at what it
  // waits for; the other looks at that flag after changing what it
  // changes (both sequentially consistent), so a wake is never lost.
  std::mutex mutex_;
  std::condition_variable writerWake_;
  std::condition_variable runWake_;
  std::atomic<bool> writerAsleep_{false};
  std::atomic<bool> runAsleep_{false};
  std::atomic<std::uint64_t> runWaitsFor_{0}; // chunks written
  std::atomic<bool> hurry_{false};            // settle(): write every chunk now
  std::atomic<bool> closed_{false};           // finish(): nothing more comes
  std::thread writer_;
};

} // namespace mbc::runner
