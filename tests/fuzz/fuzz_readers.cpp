// fuzz_readers.cpp -- mutation fuzzing of every input reader (docs/formats.md).
//
// Usage: fuzz_readers [--inputs N] [--seed S] [--reader NAME]... [--timeout SECONDS]
//                     [--memory-mb M] [--findings DIR] [--deep] [--print-rejections]
//        fuzz_readers --replay FILE --reader NAME
// For each reader (targets.h), N mutated inputs (mutator.h; input i is a pure function of
// S, the reader and i) are run in a forked worker process that reports each outcome
// through a pipe; a worker that dies is a crash at the input it was running, one silent for
// longer than the time limit is killed and counted as a hang, and a new worker resumes at
// the next input. Each outcome is one of:
//   accepted  the reader (and the checks it feeds) returned normally;
//   rejected  a std::exception whose message starts with the source name and a colon and
//             carries no internal text (below): the clear message users must get;
//   bad       any other exception: not a std::exception, std::logic_error other than
//             std::invalid_argument (internal invariants, out_of_range, length_error),
//             std::bad_alloc (a count believed before checking it), a message not naming
//             the file, naming CGAL, an assertion, a standard-library function, or longer
//             than 1000 characters;
//   crash, hang.
// Prints one CSV row per reader: reader,inputs,accepted,rejected,bad,crashes,hangs,seconds
// (with --print-rejections, first every rejection message, to read what users would see).
// Every bad, crashing or hanging input is written to the findings folder with its message
// (replay it with --replay). Exit status 1 when any input is bad, crashes or hangs.
// The worker's address space is limited to M MiB (default 2048; not under AddressSanitizer),
// so an allocation driven by a huge count fails instead of swapping.
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>
#include <stdexcept>

#include "mutator.h"
#include "targets.h"

namespace grassfire::fuzz {
namespace {

enum Outcome : unsigned char { Accepted, Rejected, Bad, Crash, Hang };

struct Options {
  std::uint64_t inputs = 100000, seed = 1;
  std::vector<std::string> readers;
  double timeout = 10;
  std::size_t memory_mb = 2048;
  std::string findings = "fuzz-findings", replay;
  bool deep = false, print_rejections = false;
};

bool internal_text(const std::string& m) {
  for (const char* marker : {"CGAL", "assertion", "Assertion", "precondition", "Precondition", "violation", "basic_string",
                             "vector::", "_M_", "stoi", "stol", "stoul", "stod", "std::", "json.exception", "invariant",
                             "bad_alloc", "bad_array"})
    if (m.find(marker) != std::string::npos) return true;
  return false;
}

std::pair<Outcome, std::string> classify(const std::string& type, const std::string& message, const std::string& source) {
  if (!type.empty()) return {Bad, type + ": " + message};
  if (message.rfind(source + ":", 0) != 0) return {Bad, "does not name the file: " + message};
  if (internal_text(message)) return {Bad, "internal text: " + message};
  if (message.size() > 1000) return {Bad, "longer than 1000 characters: " + message.substr(0, 200) + "..."};
  return {Rejected, message};
}

// Runs one input; the outcome and its message.
std::pair<Outcome, std::string> run_one(const Target& t, const std::string& input) {
  const std::string source = "fuzz-input." + t.extension;
  try {
    t.run(input, source);
    return {Accepted, ""};
  } catch (const std::bad_alloc& e) {
    return classify("std::bad_alloc", e.what(), source);
  } catch (const std::invalid_argument& e) {
    return classify("", e.what(), source);
  } catch (const std::logic_error& e) {
    return classify("std::logic_error", e.what(), source);
  } catch (const std::exception& e) {
    return classify("", e.what(), source);
  } catch (...) {
    return {Bad, "an exception that is not a std::exception"};
  }
}

std::string make_input(const Target& t, const Options& o, std::uint64_t i) {
  Rng rng(input_seed(o.seed, t.name, i));
  return mutate(t.corpus, rng);
}

void write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = write(fd, p, n);
    if (w <= 0) _exit(3);
    p += w, n -= static_cast<std::size_t>(w);
  }
}

[[noreturn]] void worker(const Target& t, const Options& o, std::uint64_t from, int fd) {
#if !defined(__SANITIZE_ADDRESS__)
  const rlim_t bytes = static_cast<rlim_t>(o.memory_mb) << 20;
  const rlimit limit{bytes, bytes};
  setrlimit(RLIMIT_AS, &limit);
#endif
  for (std::uint64_t i = from; i < o.inputs; ++i) {
    const auto [outcome, message] = run_one(t, make_input(t, o, i));
    const bool keep = outcome == Bad || (outcome == Rejected && o.print_rejections);
    const std::string m = keep ? message.substr(0, 2000) : std::string();
    const std::uint32_t len = static_cast<std::uint32_t>(m.size());
    write_all(fd, &i, sizeof i);
    write_all(fd, &outcome, 1);
    write_all(fd, &len, sizeof len);
    write_all(fd, m.data(), m.size());
  }
  _exit(0);
}

struct Counts {
  std::uint64_t n[5] = {0, 0, 0, 0, 0};
};

class ReaderRun {
 public:
  ReaderRun(const Target& t, const Options& o) : t_(t), o_(o) {}

  Counts run() {
    std::uint64_t next = 0;
    while (next < o_.inputs) next = one_worker(next);
    return counts_;
  }

 private:
  // Runs a worker from input `next`; returns the input to resume at.
  std::uint64_t one_worker(std::uint64_t next) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::cout.flush();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
      close(fds[0]);
      worker(t_, o_, next, fds[1]);
    }
    close(fds[1]);
    buffer_.clear();
    for (;;) {
      pollfd p{fds[0], POLLIN, 0};
      const int ready = poll(&p, 1, static_cast<int>(o_.timeout * 1000));
      if (ready == 0) {  // silent too long: the input `next` hangs
        kill(pid, SIGKILL);
        finish(pid, fds[0]);
        record(next, Hang, "no outcome within " + std::to_string(o_.timeout) + " s");
        return next + 1;
      }
      char chunk[65536];
      const ssize_t got = read(fds[0], chunk, sizeof chunk);
      if (got <= 0) {  // the worker ended: done, or died at input `next`
        const int status = finish(pid, fds[0]);
        if (next >= o_.inputs) return next;
        record(next, Crash, WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                                                      strsignal(WTERMSIG(status)) + ")"
                                                : "exited with status " + std::to_string(WEXITSTATUS(status)));
        return next + 1;
      }
      buffer_.append(chunk, static_cast<std::size_t>(got));
      next = drain(next);
    }
  }

  // Consumes the complete records in the buffer; returns the input after the last one.
  std::uint64_t drain(std::uint64_t next) {
    std::size_t pos = 0;
    const std::size_t head = sizeof(std::uint64_t) + 1 + sizeof(std::uint32_t);
    while (buffer_.size() - pos >= head) {
      std::uint64_t i;
      std::uint32_t len;
      std::memcpy(&i, buffer_.data() + pos, sizeof i);
      const auto outcome = static_cast<Outcome>(buffer_[pos + sizeof i]);
      std::memcpy(&len, buffer_.data() + pos + sizeof i + 1, sizeof len);
      if (buffer_.size() - pos < head + len) break;
      record(i, outcome, buffer_.substr(pos + head, len));
      pos += head + len;
      next = i + 1;
    }
    buffer_.erase(0, pos);
    return next;
  }

  static int finish(pid_t pid, int fd) {
    close(fd);
    int status = 0;
    waitpid(pid, &status, 0);
    return status;
  }

  void record(std::uint64_t i, Outcome outcome, const std::string& message) {
    ++counts_.n[outcome];
    if (outcome == Rejected && o_.print_rejections) std::cout << t_.name << " " << i << ": " << message << "\n";
    if (outcome == Accepted || outcome == Rejected) return;
    static const char* names[] = {"accepted", "rejected", "bad", "crash", "hang"};
    std::filesystem::create_directories(o_.findings);
    const std::string base = o_.findings + "/" + t_.name + "_" + std::to_string(i);
    std::ofstream(base + "." + t_.extension, std::ios::binary) << make_input(t_, o_, i);
    std::ofstream(base + ".txt") << names[outcome] << ": " << message << "\n";
    std::cerr << "fuzz_readers: " << t_.name << " input " << i << ": " << names[outcome] << ": " << message.substr(0, 300)
              << " (" << base << "." << t_.extension << ")\n";
  }

  const Target& t_;
  const Options& o_;
  Counts counts_;
  std::string buffer_;
};

Options parse_options(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if (a == "--inputs") o.inputs = std::stoull(value());
    else if (a == "--seed") o.seed = std::stoull(value());
    else if (a == "--reader") o.readers.push_back(value());
    else if (a == "--timeout") o.timeout = std::stod(value());
    else if (a == "--memory-mb") o.memory_mb = std::stoull(value());
    else if (a == "--findings") o.findings = value();
    else if (a == "--replay") o.replay = value();
    else if (a == "--deep") o.deep = true;
    else if (a == "--print-rejections") o.print_rejections = true;
    else throw std::invalid_argument("unknown option " + a + " (see the top of tests/fuzz/fuzz_readers.cpp)");
  }
  return o;
}

int replay(const std::vector<Target>& targets, const Options& o) {
  if (o.readers.size() != 1) throw std::invalid_argument("--replay needs one --reader");
  for (const Target& t : targets)
    if (t.name == o.readers[0]) {
      std::ifstream in(o.replay, std::ios::binary);
      std::ostringstream ss;
      ss << in.rdbuf();
      const auto [outcome, message] = run_one(t, ss.str());
      static const char* names[] = {"accepted", "rejected", "bad"};
      std::cout << names[outcome] << (message.empty() ? "" : ": " + message) << "\n";
      return outcome == Bad ? 1 : 0;
    }
  throw std::invalid_argument("unknown reader " + o.readers[0]);
}

int main_fuzz(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  const std::vector<Target> targets = fuzz_targets(GF_TEST_DATA, GF_PROJECT_DATA, o.deep);
  if (!o.replay.empty()) return replay(targets, o);
  std::cout << "reader,inputs,accepted,rejected,bad,crashes,hangs,seconds\n";
  bool clean = true;
  for (const Target& t : targets) {
    if (!o.readers.empty() && std::find(o.readers.begin(), o.readers.end(), t.name) == o.readers.end()) continue;
    const auto start = std::chrono::steady_clock::now();
    const Counts c = ReaderRun(t, o).run();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << t.name << ',' << o.inputs << ',' << c.n[Accepted] << ',' << c.n[Rejected] << ',' << c.n[Bad] << ','
              << c.n[Crash] << ',' << c.n[Hang] << ',' << seconds << std::endl;
    clean = clean && c.n[Bad] + c.n[Crash] + c.n[Hang] == 0;
  }
  return clean ? 0 : 1;
}

}  // namespace
}  // namespace grassfire::fuzz

int main(int argc, char** argv) {
  try {
    return grassfire::fuzz::main_fuzz(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "fuzz_readers: " << e.what() << "\n";
    return 2;
  }
}
