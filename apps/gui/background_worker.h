// One background thread that runs the newest job it was given: submitting a
// job replaces any job still queued and cancels the running one. The GUI
// renders and computes debugger views this way, so the window never waits.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace pathlab::gui {

template <class Job, class Result>
class BackgroundWorker {
 public:
  // work(job, cancel, publish): publish results as they come (a progressive
  // render publishes once per pass) and return soon after cancel is set.
  using Work = std::function<void(const Job&, const std::atomic<bool>& cancel,
                                  const std::function<void(Result)>& publish)>;

  explicit BackgroundWorker(Work work) : work_(std::move(work)), thread_([this] { run(); }) {}

  ~BackgroundWorker() {
    {
      std::lock_guard lock(mutex_);
      quit_ = true;
      cancel_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }

  void submit(Job job) {
    {
      std::lock_guard lock(mutex_);
      queued_ = std::move(job);
      cancel_ = true;
    }
    wake_.notify_one();
  }

  // The newest result not yet taken, if any.
  std::optional<Result> take() {
    std::lock_guard lock(mutex_);
    return std::exchange(result_, std::nullopt);
  }

  // Nothing queued and nothing running.
  bool idle() const {
    std::lock_guard lock(mutex_);
    return !queued_ && !running_;
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return quit_ || queued_; });
      if (quit_) return;
      Job job = std::move(*queued_);
      queued_.reset();
      cancel_ = false;
      running_ = true;
      lock.unlock();
      work_(job, cancel_, [this](Result result) {
        std::lock_guard resultLock(mutex_);
        result_ = std::move(result);
      });
      lock.lock();
      running_ = false;
    }
  }

  Work work_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> queued_;
  std::optional<Result> result_;
  std::atomic<bool> cancel_{false};
  bool running_ = false;
  bool quit_ = false;
  std::thread thread_;  // last: starts after the members it uses exist
};

}  // namespace pathlab::gui
