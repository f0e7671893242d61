// The floor a reader of G-code stands on (issue 19's "physical floor"): the
// file mapped, every number after a letter read with usina's own decimal
// routine, nothing else (no words, no blocks, no interpreter). Whatever a
// verb does costs more than this; run_bench.sh prints each verb's speed
// beside it, so a figure from a slower or a faster machine can be compared.
//
//   number_floor FILE [RUNS]   prints: bytes numbers sum seconds MB/s
//
// seconds: the least CPU time (user + sys of this process, mapping and
// page faults included) of RUNS passes (default 5), each on a new mapping.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include "gcode/decimal.hpp"

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const auto sec = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) * 1e-6;
  };
  return sec(u.ru_utime) + sec(u.ru_stime);
}

struct Pass {
  long numbers = 0;
  double sum = 0.0;  // printed, so the reading is not optimised away
};

Pass read_numbers(std::string_view text) {
  Pass p;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i++];
    if (c < 'A' || c > 'Z') continue;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) ++i;
    const usina::gcode::Decimal d = usina::gcode::scan_decimal(text, i);
    if (d.digits == 0) continue;
    p.sum += d.value;
    ++p.numbers;
    i = d.end;
  }
  return p;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: number_floor FILE [RUNS]\n");
    return 2;
  }
  const int runs = argc == 3 ? std::atoi(argv[2]) : 5;
  if (runs < 1 || runs > 1000) {
    std::fprintf(stderr, "number_floor: RUNS must be within 1 and 1000\n");
    return 2;
  }
  double best = 1e300;
  Pass pass;

  struct stat st {};

  for (int r = 0; r < runs; ++r) {
    const double start = cpu_seconds();
    const int fd = open(argv[1], O_RDONLY | O_CLOEXEC);
    if (fd < 0 || fstat(fd, &st) != 0) {
      std::perror(argv[1]);
      if (fd >= 0) close(fd);
      return 1;
    }
    if (st.st_size == 0) {  // mmap refuses a length of 0; errno would say nothing
      std::fprintf(stderr, "%s: empty file\n", argv[1]);
      close(fd);
      return 1;
    }
    const auto size = static_cast<std::size_t>(st.st_size);
    void* map = mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (map == MAP_FAILED) {
      std::perror("mmap");
      return 1;
    }
    pass = read_numbers({static_cast<const char*>(map), size});
    munmap(map, size);
    best = std::min(best, cpu_seconds() - start);
  }
  std::printf("%lld %ld %.6g %.4f %.1f\n", static_cast<long long>(st.st_size), pass.numbers,
              pass.sum, best, static_cast<double>(st.st_size) / 1e6 / best);
  return 0;
}
