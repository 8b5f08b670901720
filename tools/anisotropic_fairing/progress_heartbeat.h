// A line on stderr whenever the program has said nothing for a while: which phase it is in and for how
// long. The library reports accepted steps only; reading, set-up, a step retried after rejections and the
// write-back can each take seconds on a large or quantised mesh, and a silent program looks hung.

#ifndef AF_TOOL_PROGRESS_HEARTBEAT_H
#define AF_TOOL_PROGRESS_HEARTBEAT_H

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

class Progress_heartbeat
{
  typedef std::chrono::steady_clock Clock;

public:
  /// `interval` seconds of silence make a line; 0: never.
  explicit Progress_heartbeat(double interval) : interval_(interval)
  {
    if(interval_ > 0) thread_ = std::thread([this] { watch(); });
  }
  ~Progress_heartbeat()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_all();
    if(thread_.joinable()) thread_.join();
  }
  Progress_heartbeat(const Progress_heartbeat&) = delete;
  Progress_heartbeat& operator=(const Progress_heartbeat&) = delete;

  /// From now on in `what` (e.g. "reading in.off"); also counts as a line said.
  void phase(const std::string& what)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = what;
    phase_start_ = last_line_ = Clock::now();
  }
  /// A line was printed by someone else.
  void said()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    last_line_ = Clock::now();
  }

private:
  void watch()
  {
    const std::chrono::duration<double> interval(interval_);
    std::unique_lock<std::mutex> lock(mutex_);
    while(!stop_)
    {
      const Clock::time_point due = last_line_ + std::chrono::duration_cast<Clock::duration>(interval);
      if(Clock::now() < due) { wake_.wait_until(lock, due); continue; }
      if(!phase_.empty())
        std::fprintf(stderr, "anisotropic_fairing: %s (%.1f s so far)\n", phase_.c_str(),
                     std::chrono::duration<double>(Clock::now() - phase_start_).count());
      last_line_ = Clock::now();
    }
  }

  double interval_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::string phase_;
  Clock::time_point phase_start_ = Clock::now(), last_line_ = Clock::now();
  bool stop_ = false;
  std::thread thread_;
};

#endif // AF_TOOL_PROGRESS_HEARTBEAT_H
