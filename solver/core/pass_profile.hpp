#pragma once
// Where a step's time goes: the wall time of every backend launch (a pass, named after its functor:
// StressForcePass, DensitySumPass, ...) under the stage that launched it (StageScope). The backends
// time each launch while an engine records into its profile (ProfileRecording, around a step); on
// a GPU with events, read back when the profile is resolved, so that no launch waits for one.
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cxxabi.h>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <utility>
#include <vector>

namespace psph {

struct PassTime {
  std::string stage, pass;  // pass empty: the stage's total
  long calls = 0;
  double seconds = 0;
};

class PassProfile {
 public:
  // Waits for a device launch's timing, returns its seconds and frees its handle (the backend's).
  using Resolver = double (*)(void* handle);

  // `stage` a string literal, `pass` a string that outlives the profile (pass_name_of): kept by
  // address, so that a launch costs no string work.
  void add(const char* stage, const std::string& pass, double seconds) {
    Entry& e = times_[{stage, &pass}];
    ++e.calls, e.seconds += seconds;
  }
  void defer(const char* stage, const std::string* pass, void* handle, Resolver resolver) {
    pending_.push_back({stage, pass, handle, resolver});
    if (pending_.size() >= 4096) resolve();  // bounded: a long GPU run reads its events as it goes
  }
  void resolve() {
    for (const Pending& p : pending_) add(p.stage, *p.pass, p.resolver(p.handle));
    pending_.clear();
  }
  // Every pass, the most expensive first.
  std::vector<PassTime> passes() {
    resolve();
    std::map<std::pair<std::string, std::string>, PassTime> named;  // one literal may have several addresses
    for (const auto& kv : times_) {
      PassTime& t = named[{kv.first.first, *kv.first.second}];
      t.stage = kv.first.first, t.pass = *kv.first.second;
      t.calls += kv.second.calls, t.seconds += kv.second.seconds;
    }
    std::vector<PassTime> out;
    for (const auto& kv : named) out.push_back(kv.second);
    sort_by_time(out);
    return out;
  }
  // Each stage's passes summed (pass empty; calls: its launches), the most expensive first.
  std::vector<PassTime> stages() {
    std::map<std::string, PassTime> by_stage;
    for (const PassTime& p : passes()) {
      PassTime& s = by_stage[p.stage];
      s.stage = p.stage, s.calls += p.calls, s.seconds += p.seconds;
    }
    std::vector<PassTime> out;
    for (const auto& kv : by_stage) out.push_back(kv.second);
    sort_by_time(out);
    return out;
  }
  double seconds() {
    double s = 0;
    for (const PassTime& p : passes()) s += p.seconds;
    return s;
  }
  void clear() {
    resolve();
    times_.clear();
  }

 private:
  struct Entry {
    long calls = 0;
    double seconds = 0;
  };
  struct Pending {
    const char* stage;
    const std::string* pass;
    void* handle;
    Resolver resolver;
  };
  static void sort_by_time(std::vector<PassTime>& v) {
    std::stable_sort(v.begin(), v.end(), [](const PassTime& a, const PassTime& b) { return a.seconds > b.seconds; });
  }
  std::map<std::pair<const char*, const std::string*>, Entry> times_;
  std::vector<Pending> pending_;
};

// The profile this thread's launches record into (none: not recorded) and the stage launching.
struct ProfileFocus {
  PassProfile* profile = nullptr;
  const char* stage = "engine";
};
inline ProfileFocus& profile_focus() {
  thread_local ProfileFocus focus;
  return focus;
}

// Launches on this thread record into `p` while it lives.
class ProfileRecording {
 public:
  explicit ProfileRecording(PassProfile& p) : before_(profile_focus()) { profile_focus() = {&p, "engine"}; }
  ~ProfileRecording() { profile_focus() = before_; }
  ProfileRecording(const ProfileRecording&) = delete;
  ProfileRecording& operator=(const ProfileRecording&) = delete;

 private:
  ProfileFocus before_;
};

// The launches while it lives are not recorded (a machinery's inner launches, timed as a whole).
class ProfilePause {
 public:
  ProfilePause() : before_(profile_focus().profile) { profile_focus().profile = nullptr; }
  ~ProfilePause() { profile_focus().profile = before_; }
  ProfilePause(const ProfilePause&) = delete;
  ProfilePause& operator=(const ProfilePause&) = delete;

 private:
  PassProfile* before_;
};

// The launches while it lives are the stage `name`'s (a string literal).
class StageScope {
 public:
  explicit StageScope(const char* name) : before_(profile_focus().stage) { profile_focus().stage = name; }
  ~StageScope() { profile_focus().stage = before_; }
  StageScope(const StageScope&) = delete;
  StageScope& operator=(const StageScope&) = delete;

 private:
  const char* before_;
};

// A functor's type name without namespaces and template arguments ("StressForcePass"); a lambda
// keeps the function it is in ("stats()::{lambda(int)#1}").
inline std::string readable_pass_name(const char* mangled) {
  int status = 0;
  const std::unique_ptr<char, void (*)(void*)> full(abi::__cxa_demangle(mangled, nullptr, nullptr, &status), std::free);
  const std::string name = status == 0 && full ? full.get() : mangled;
  std::vector<std::string> parts{""};
  int depth = 0;
  for (std::size_t k = 0; k < name.size(); ++k) {
    const char c = name[k];
    if (c == '<') ++depth;
    if (depth == 0 && c == ':' && k + 1 < name.size() && name[k + 1] == ':') {
      parts.emplace_back(), ++k;
      continue;
    }
    if (depth == 0) parts.back() += c;
    if (c == '>') --depth;
  }
  const std::string& last = parts.back();
  if (!last.empty() && last[0] == '{' && parts.size() > 1) return parts[parts.size() - 2] + "::" + last;
  return last;
}
// A wrapper names itself after what it wraps (`using named_as = F;`).
template <class F, class = void>
struct ProfiledAs {
  using type = F;
};
template <class F>
struct ProfiledAs<F, std::void_t<typename F::named_as>> {
  using type = typename ProfiledAs<typename F::named_as>::type;
};
template <class F>
const std::string& pass_name_of() {
  static const std::string name = readable_pass_name(typeid(typename ProfiledAs<F>::type).name());
  return name;
}

// Times one launch on the host into the focused profile, if any.
class HostPassClock {
 public:
  explicit HostPassClock(const std::string& pass) : focus_(profile_focus()), pass_(pass) {
    if (focus_.profile) start_ = std::chrono::steady_clock::now();
  }
  ~HostPassClock() {
    if (focus_.profile)
      focus_.profile->add(focus_.stage, pass_,
                          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  HostPassClock(const HostPassClock&) = delete;
  HostPassClock& operator=(const HostPassClock&) = delete;

 private:
  ProfileFocus focus_;
  const std::string& pass_;
  std::chrono::steady_clock::time_point start_{};
};

}  // namespace psph
