// Google Benchmark of the DNC program store (issue 13's speed targets):
// - the normalised and the plain diff of two 1 MB programs, the second
//   renumbered, with CR LF line ends and one block in a hundred changed;
// - the library search's scan of a 30 MB program (store_facts.hpp), a tool
//   change and a comment every 1,000 blocks;
// - 10,000 revisions stored one upload (one transaction, with its check and
//   audit entry) at a time, then listed, on SQLite in a temporary folder, and
//   on PostgreSQL when USINA_BENCH_PG names a database URL (for example one
//   started with tests/dnc/pg_cluster.sh start DIR).
// Never asserts times.
#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <benchmark/benchmark.h>

#include "dnc/store_facts.hpp"
#include "dnc/store_program_diff.hpp"
#include "dnc/store_revisions.hpp"

namespace {

using namespace usina::dnc;

// About `bytes` of program; `renumber` and `crlf` give the second one's form,
// and every `change_every`-th feed gets another value.
std::string big_program(std::size_t bytes, int step, bool crlf, int change_every) {
  std::string out = "%\nO1000\n";
  const char* eol = crlf ? "\r\n" : "\n";
  for (int n = 1; out.size() < bytes; ++n) {
    const bool changed = change_every > 0 && n % change_every == 0;
    out += "N" + std::to_string(n * step) + " G1 X" + std::to_string(n % 500) + ".25 Y" +
           std::to_string((n * 7) % 300) + (changed ? ".5" : ".0") + " F1200" + eol;
  }
  return out + "M30" + eol + "%" + eol;
}

void BM_NormalisedDiff1MB(benchmark::State& state) {
  const std::string a = big_program(1 << 20, 10, false, 0);
  const std::string b = big_program(1 << 20, 5, true, 100);
  std::size_t changed = 0;
  for (auto _ : state) {
    const ProgramDiff d = normalised_diff(a, b);
    changed = d.diff.deleted + d.diff.inserted;
    benchmark::DoNotOptimize(changed);
  }
  state.counters["blocks_changed"] = static_cast<double>(changed);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * (a.size() + b.size())));
}

BENCHMARK(BM_NormalisedDiff1MB)->Unit(benchmark::kMillisecond);

void BM_PlainDiff1MB(benchmark::State& state) {
  const std::string a = big_program(1 << 20, 10, false, 0);
  const std::string b = big_program(1 << 20, 10, false, 100);
  for (auto _ : state) {
    const ProgramDiff d = plain_diff(a, b);
    benchmark::DoNotOptimize(d.diff.deleted);
  }
}

BENCHMARK(BM_PlainDiff1MB)->Unit(benchmark::kMillisecond);

void BM_ProgramFacts30MB(benchmark::State& state) {
  std::string text = "%\nO1000 (FACTS BENCH)\n";
  for (int n = 1; text.size() < (30u << 20); ++n) {
    if (n % 1000 == 0)
      text += "T" + std::to_string(n / 1000 % 40 + 1) + " M6 (TOOL " + std::to_string(n) + ")\n";
    text += "N" + std::to_string(n * 10) + " G1 X" + std::to_string(n % 500) + ".25 Y" +
            std::to_string((n * 7) % 300) + ".0 F1200\n";
  }
  std::size_t tools = 0;
  for (auto _ : state) {
    const ProgramFacts f = read_facts(text, "fanuc");
    tools = f.tools.size();
    benchmark::DoNotOptimize(tools);
  }
  state.counters["tools"] = static_cast<double>(tools);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * text.size()));
}

BENCHMARK(BM_ProgramFacts30MB)->Unit(benchmark::kMillisecond);

constexpr int kRevisions = 10'000;

// Stores kRevisions small programs (100 programs of 100 revisions), then lists them.
void store_and_list(benchmark::State& state, const std::string& where) {
  StoreOptions o;
  auto s = Store::open(where, o);
  if (!s) {
    state.SkipWithError(s.error().message.c_str());
    return;
  }
  double put_s = 0.0;
  double list_s = 0.0;
  std::size_t listed = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < kRevisions; ++i) {
      const std::string text = "G21 G90\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X" + std::to_string(i) +
                               " Y5\nM2\n(" + where + ")\n";
      auto put =
          put_revision(**s, {"P" + std::to_string(i % 100), "", "rs274ngc", text, "bench", nullptr},
                       {"bench", "bench"});
      if (!put) state.SkipWithError(put.error().message.c_str());
    }
    const auto t1 = std::chrono::steady_clock::now();
    RevisionQuery all;
    all.limit = kRevisions;
    listed = list_revisions(**s, all).value().size();
    const auto t2 = std::chrono::steady_clock::now();
    put_s = std::chrono::duration<double>(t1 - t0).count();
    list_s = std::chrono::duration<double>(t2 - t1).count();
  }
  state.counters["put_per_s"] = kRevisions / put_s;
  state.counters["list_ms"] = list_s * 1000.0;
  state.counters["listed"] = static_cast<double>(listed);
}

void BM_Store10kRevisionsSqlite(benchmark::State& state) {
  char tmpl[] = "/tmp/usina-bench-store-XXXXXX";
  if (::mkdtemp(tmpl) == nullptr) return state.SkipWithError("no temporary folder");
  store_and_list(state, std::string(tmpl) + "/store");
  std::error_code ec;
  std::filesystem::remove_all(tmpl, ec);
}

BENCHMARK(BM_Store10kRevisionsSqlite)->Iterations(1)->Unit(benchmark::kSecond);

void BM_Store10kRevisionsPostgres(benchmark::State& state) {
  const char* url = std::getenv("USINA_BENCH_PG");
  if (url == nullptr) return state.SkipWithError("set USINA_BENCH_PG to a postgresql:// URL");
  store_and_list(state, url);
}

BENCHMARK(BM_Store10kRevisionsPostgres)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
