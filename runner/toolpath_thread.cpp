// The toolpath's writer thread (see toolpath_thread.h).
#include "runner/toolpath_thread.h"

#include <mbc/toolpath_json.h>

#include <algorithm>
#include <cstring>
#include <sched.h>

namespace mbc::runner {

std::size_t MotionTargets::take(const mbrt_motion& motion) const {
  std::size_t bytes = toolpath != nullptr ? toolpath->write(motion) : 0;
  if (svg != nullptr) {
    bytes += svg->add(motion);
  }
  if (html != nullptr) {
    bytes += html->add(motion);
  }
  return bytes;
}

std::size_t MotionTargets::bound(const mbrt_motion& motion) const {
  std::size_t bytes = toolpath != nullptr ? toolpathJsonBound(motion) : 0;
  if (svg != nullptr) {
    bytes += SvgWriter::growthBound(motion);
  }
  if (html != nullptr) {
    bytes += HtmlWriter::growthBound(motion);
  }
  return bytes;
}

MotionTargets MotionTargets::except(const MotionTargets& taken) const {
  return {taken.toolpath != nullptr ? nullptr : toolpath,
          taken.svg != nullptr ? nullptr : svg,
          taken.html != nullptr ? nullptr : html};
}

ToolpathThread::ToolpathThread(const MotionTargets& targets)
    // Default-initialised: the slots are not cleared, a page is touched
    // when a chunk first fills it.
    : targets_(targets),
      drawing_(targets.svg != nullptr || targets.html != nullptr),
      ring_(new Chunk[kRing]), writer_([this] { write(); }) {
}

ToolpathThread::~ToolpathThread() {
  finish();
}

MotionTargets ToolpathThread::wanted(WriterThread choice,
                                     const MotionTargets& outputs) {
  if (choice == WriterThread::Off ||
      (choice == WriterThread::Auto && usableCores() < 2)) {
    return {};
  }
  MotionTargets threaded = outputs;
  if (choice == WriterThread::Auto && outputs.toolpath != nullptr &&
      outputs.toolpath->direct()) {
    threaded.toolpath = nullptr;
  }
  return threaded;
}

std::string ToolpathThread::madeText() const {
  std::string made;
  for (const auto& [there, name] :
       {std::pair{targets_.toolpath != nullptr, "the toolpath"},
        std::pair{targets_.svg != nullptr, "the SVG"},
        std::pair{targets_.html != nullptr, "the HTML page"}}) {
    if (there) {
      made += made.empty() ? name : std::string(", ") + name;
    }
  }
  return made;
}

unsigned ToolpathThread::usableCores() {
  // The cores this process may run on (taskset, a container's cpuset),
  // which may be fewer than the machine's.
  cpu_set_t cores;
  if (sched_getaffinity(0, sizeof cores, &cores) == 0) {
    return static_cast<unsigned>(CPU_COUNT(&cores));
  }
  return std::thread::hardware_concurrency();
}

const char* ToolpathThread::kept(const char* name, const char*& last) {
  if (name == nullptr) {
    return nullptr;
  }
  if (last == nullptr || std::strcmp(last, name) != 0) {
    // A set's strings stay where they are while others are added.
    last = names_.insert(name).first->c_str();
  }
  return last;
}

std::size_t ToolpathThread::push(const mbrt_motion& motion) {
  if (count_ == 0 && filling_ >= kRing) {
    // The chunk is free once the writer is past it; wait for more room
    // than that, so that the writer is not asked after every chunk.
    const std::uint64_t free = filling_ - kRing + 1;
    if (written_.load(std::memory_order_acquire) < free) {
      waitForWriter(std::max(free, filling_ + kRoomToWake - kRing));
    }
  }
  mbrt_motion& to = ring_[filling_ % kRing].slots[count_++].motion;
  to.kind = motion.kind;
  to.axis_count = motion.axis_count;
  to.axis_names = motion.axis_names;
  // Whole arrays: a copy of fixed size is a few vector moves, a copy of
  // axis_count doubles a call to memmove.
  std::copy_n(motion.end, MBRT_MAX_AXES, to.end);
  std::copy_n(motion.machine, MBRT_MAX_AXES, to.machine);
  to.feed = motion.feed;
  to.center_axes[0] = motion.center_axes[0];
  to.center_axes[1] = motion.center_axes[1];
  to.center[0] = motion.center[0];
  to.center[1] = motion.center[1];
  to.decimals = motion.decimals;
  to.line = motion.line;
  to.program = kept(motion.program, lastProgram_);
  to.cycle = motion.cycle;
  if (drawing_) {
    to.diameter_mask = motion.diameter_mask;
    std::copy_n(motion.start, MBRT_MAX_AXES, to.start);
    std::copy_n(motion.programmed, MBRT_MAX_AXES, to.programmed);
    to.file = kept(motion.file, lastFile_);
  }
  if (count_ == kChunk) {
    publish();
  }
  const std::size_t bound = targets_.bound(motion);
  bounded_ += bound;
  return bound;
}

void ToolpathThread::publish() {
  if (count_ == 0) {
    return;
  }
  ring_[filling_ % kRing].size = count_;
  count_ = 0;
  ++filling_;
  published_.store(filling_, std::memory_order_seq_cst);
  if (filling_ - written_.load(std::memory_order_acquire) >= kWakeBatch) {
    wakeWriter();
  }
}

void ToolpathThread::wakeWriter() {
  if (writerAsleep_.load(std::memory_order_seq_cst) &&
      writerAsleep_.exchange(false)) {
    const std::lock_guard lock(mutex_);
    writerWake_.notify_one();
  }
}

void ToolpathThread::waitForWriter(std::uint64_t chunk) {
  std::unique_lock lock(mutex_);
  runWaitsFor_.store(chunk);
  runAsleep_.store(true);
  if (written_.load() >= chunk) {
    runAsleep_.store(false);
    return;
  }
  runWake_.wait(lock, [this] { return !runAsleep_.load(); });
}

std::uint64_t ToolpathThread::settle() {
  publish();
  hurry_.store(true);
  wakeWriter();
  if (written_.load(std::memory_order_acquire) < filling_) {
    waitForWriter(filling_);
  }
  hurry_.store(false);
  const std::uint64_t exact = exact_.load(std::memory_order_acquire);
  const std::uint64_t over =
      (bounded_ - settledBounds_) - (exact - settledExact_);
  settledBounds_ = bounded_;
  settledExact_ = exact;
  return over;
}

void ToolpathThread::finish() {
  if (!writer_.joinable()) {
    return;
  }
  publish();
  closed_.store(true);
  wakeWriter();
  writer_.join();
}

void ToolpathThread::write() {
  std::uint64_t next = 0; // the chunk to write
  for (;;) {
    if (next < published_.load(std::memory_order_acquire)) {
      const Chunk& chunk = ring_[next % kRing];
      std::uint64_t bytes = 0;
      for (std::size_t i = 0; i < chunk.size; ++i) {
        bytes += targets_.take(chunk.slots[i].motion);
      }
      exact_.fetch_add(bytes, std::memory_order_relaxed);
      written_.store(++next, std::memory_order_seq_cst);
      if (runAsleep_.load(std::memory_order_seq_cst) &&
          next >= runWaitsFor_.load() && runAsleep_.exchange(false)) {
        const std::lock_guard lock(mutex_);
        runWake_.notify_one();
      }
      continue;
    }
    std::unique_lock lock(mutex_);
    writerAsleep_.store(true);
    const auto ready = [this, next] {
      const std::uint64_t published = published_.load();
      return closed_.load() ||
             (published > next &&
              (published - next >= kWakeBatch || hurry_.load()));
    };
    if (ready()) {
      writerAsleep_.store(false);
    } else {
      writerWake_.wait(lock, [this] { return !writerAsleep_.load(); });
    }
    if (closed_.load() && next == published_.load()) {
      return; // everything written
    }
  }
}

} // namespace mbc::runner
