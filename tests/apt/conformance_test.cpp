// The three programs of ../shared/conformance/apt against the IBM
// processor's CL records. The records are compared statement by statement
// (the groups behind each 1000-class record): every group usina writes must
// match IBM's (class, subclass, word count, numbers within 1e-5, text); a
// group usina does not write must have an error that says usina's APT does
// not run that statement yet. The test prints which groups match and which
// are not produced, and fails when fewer match than the last slice reached
// (since the second slice: every statement of the three programs).
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

#include "apt/lexer.hpp"
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

const std::string kDir = std::string(USINA_SHARED_DIR) + "/conformance/apt/";

using Words = std::vector<std::string>;
using Group = std::vector<Words>;  // the records after a 1000 record, as printed

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// ISN -> the records of that statement, from a record print.
std::map<int, Group> groups(const std::string& print) {
  std::map<int, Group> out;
  const std::regex word("'[^']*'|[^ ]+");
  std::istringstream in(print);
  std::string line;
  int isn = 0;
  while (std::getline(in, line)) {
    Words w;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), word);
         it != std::sregex_iterator(); ++it)
      w.push_back(it->str());
    if (w.size() < 4) continue;
    w.erase(w.begin());  // recno
    if (w[0] == "1000") {
      isn = std::stoi(w[1]);
      out[isn];
      continue;
    }
    out[isn].push_back(w);
  }
  return out;
}

bool same_word(const std::string& a, const std::string& b) {
  if (a == b) return true;
  if (a.empty() || b.empty() || a[0] == '\'' || a[0] == '#' || b[0] == '\'' || b[0] == '#')
    return false;
  return std::fabs(std::stod(a) - std::stod(b)) <= 1e-5;
}

bool same_group(const Group& a, const Group& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return false;
    for (std::size_t k = 0; k < a[i].size(); ++k)
      if (!same_word(a[i][k], b[i][k])) return false;
  }
  return true;
}

struct Tally {
  int matched = 0;
  int not_produced = 0;
};

Tally compare(const std::string& name) {
  const std::string text = slurp(kDir + name + ".apt");
  const AptRun r = run(text);
  const auto ibm = groups(slurp(kDir + name + ".cldump.txt"));
  const auto ours = groups(record_print(r.result.records));
  const auto sts = split_statements(text, 0);
  Tally t;
  for (const auto& [isn, want] : ibm) {
    const auto got = ours.find(isn);
    const std::uint32_t line = sts.at(static_cast<std::size_t>(isn - 1)).loc.line;
    if (got == ours.end()) {
      bool said = false;
      for (const core::Diagnostic& d : r.diags.all())
        said = said || (d.code == core::Code::AptNotSupported && d.loc.line == line);
      EXPECT_TRUE(said) << name << " ISN " << isn << " (line " << line
                        << "): no records and no error saying why";
      std::cout << name << " ISN " << isn << ": not produced yet (" << want.size() << " records)\n";
      ++t.not_produced;
      continue;
    }
    EXPECT_TRUE(same_group(got->second, want)) << name << " ISN " << isn << " differs";
    if (same_group(got->second, want)) ++t.matched;
  }
  for (const auto& [isn, got] : ours)
    EXPECT_TRUE(ibm.count(isn)) << name << " ISN " << isn << ": usina writes records IBM does not";
  std::cout << name << ": " << t.matched << " statements match, " << t.not_produced
            << " not produced yet\n";
  return t;
}

TEST(AptConformance, IbmSampleEx10_1) {
  const Tally t = compare("ibm360_sample_ex10_1");
  // Every statement, the contouring ones (GO, GOLFT, GORGT, GOFWD, arcs) too.
  EXPECT_GE(t.matched, 21);
  EXPECT_EQ(t.not_produced, 0);
}

TEST(AptConformance, PersonalAptSample) {
  const Tally t = compare("personal_apt_sample");
  EXPECT_GE(t.matched, 12);
  EXPECT_EQ(t.not_produced, 0);
}

TEST(AptConformance, WikipediaApt1) {
  const Tally t = compare("wikipedia_apt1_metric");
  EXPECT_GE(t.matched, 15);
  EXPECT_EQ(t.not_produced, 0);
}

}  // namespace
}  // namespace usina::apt::test
