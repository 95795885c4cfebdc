// The paper's claims checked across a study's cases (cases/study/study_claims.hpp), on study
// tables written by hand: each verdict follows its stated criterion, unfinished cases do not
// count, and a claim without the cases it needs is undetermined.
#include <gtest/gtest.h>

#include "cases/study/study_claims.hpp"

using namespace granshock;

namespace {

nlohmann::ordered_json row(const std::string& name, double d_over_d, double mach, double delta,
                           double wake = 0.02, const std::string& status = "finished") {
  return {{"case", name},
          {"status", status},
          {"scene.D_over_d", d_over_d},
          {"ma_inf_target", mach},
          {"delta_over_D", delta},
          {"delta_over_D_err", 0.01},
          {"shock_layer_phi_mean", 0.48},
          {"hot_region_subsonic_fraction", 0.8},
          {"upstream_ma_peak_over_ma_inf", 1.4},
          {"wake_phi_over_phi_inf", wake}};
}

const StudyClaim& find(const std::vector<StudyClaim>& claims, const std::string& start) {
  for (const StudyClaim& c : claims)
    if (c.claim.rfind(start, 0) == 0) return c;
  throw std::runtime_error("no claim " + start);
}

TEST(StudyClaims, VerdictsFollowTheirCriteria) {
  StudyTable t;
  // Two sizes at two Mach numbers; delta/D falls with Ma and varies by 10 % with D/d.
  t.rows = {row("d10_u1000", 10, 5.9, 0.26), row("d10_u2375", 10, 13.7, 0.21),
            row("d50_u1000", 50, 5.9, 0.24), row("d50_u2375", 50, 13.7, 0.20, 0.5),
            // Unfinished cases never count, whatever their numbers say.
            row("d100_u1000", 100, 5.9, 0.9, 0.02, "unfinished")};
  const std::vector<StudyClaim> claims = check_paper_claims(t);
  ASSERT_EQ(claims.size(), 6u);
  EXPECT_EQ(find(claims, "delta/D falls").verdict, "holds")
      << find(claims, "delta/D falls").numbers;
  EXPECT_NE(find(claims, "delta/D falls")
                .numbers.find(
                    "D/d 10: 0.260 +- 0.010 (Ma 5.9) 0.210 +- 0.010 (Ma 13.7) [fall 3.5 errors]"),
            std::string::npos)
      << find(claims, "delta/D falls").numbers;
  const StudyClaim& constant = find(claims, "delta/D is nearly constant");
  EXPECT_EQ(constant.verdict, "holds") << constant.numbers;
  EXPECT_NE(constant.numbers.find("spread 8.0 %"), std::string::npos) << constant.numbers;
  EXPECT_EQ(find(claims, "phi is about 0.5").verdict, "holds");
  EXPECT_EQ(find(claims, "the hot region").verdict, "holds");
  EXPECT_EQ(find(claims, "the local Ma").verdict, "holds");
  // One case has a wake at half of phi_inf.
  EXPECT_EQ(find(claims, "the wake").verdict, "does not hold");
  EXPECT_NE(find(claims, "the wake").numbers.find("d50_u2375 0.5"), std::string::npos);

  // A fall within the errors: it holds, but the verdict says it is not significant.
  t.rows = {row("a", 10, 5.9, 0.20), row("b", 10, 13.7, 0.19)};
  EXPECT_EQ(find(check_paper_claims(t), "delta/D falls").verdict,
            "holds, but not by two errors everywhere");

  // delta/D rising with Ma at one size, and by 50 % with D/d: both claims fail.
  t.rows = {row("a", 10, 5.9, 0.20), row("b", 10, 13.7, 0.25), row("c", 50, 5.9, 0.30)};
  const std::vector<StudyClaim> failing = check_paper_claims(t);
  EXPECT_EQ(find(failing, "delta/D falls").verdict, "does not hold");
  EXPECT_EQ(find(failing, "delta/D is nearly constant").verdict, "does not hold");
}

// A sweep study (studies/future_work.toml): cases that differ from the base in phi_inf or
// e are not points of the Ma_inf series, however large their delta/D. Only the Ma axis
// (the base and the cases that change Ma alone) is judged.
TEST(StudyClaims, SweepCasesOnOtherAxesAreNotComparedAlongMa) {
  StudyTable t;
  const auto with = [](nlohmann::ordered_json r, double phi, double e) {
    r["scene.phi_inf"] = phi;
    r["scene.restitution"] = e;
    return r;
  };
  t.rows = {with(row("base", 20, 5.9, 0.30), 0.1, 0.5), with(row("Ma-9", 20, 9, 0.25), 0.1, 0.5),
            with(row("Ma-13.7", 20, 13.7, 0.20), 0.1, 0.5),
            with(row("phi-0.3", 20, 5.9, 0.57), 0.3, 0.5),
            with(row("e-0.9", 20, 5.9, 0.35), 0.1, 0.9)};
  const std::vector<StudyClaim> claims = check_paper_claims(t);
  const StudyClaim& falls = find(claims, "delta/D falls");
  EXPECT_EQ(falls.verdict, "holds") << falls.numbers;
  EXPECT_EQ(falls.numbers.find("0.570"), std::string::npos) << falls.numbers;
  EXPECT_EQ(falls.numbers.find("0.350"), std::string::npos) << falls.numbers;
  // No two cases differ in D/d alone.
  EXPECT_EQ(find(claims, "delta/D is nearly constant").verdict, "undetermined");
}

TEST(StudyClaims, UndeterminedWithoutTheCasesTheyNeed) {
  StudyTable t;
  t.rows = {row("only", 20, 5.9, 0.25)};
  const std::vector<StudyClaim> claims = check_paper_claims(t);
  EXPECT_EQ(find(claims, "delta/D falls").verdict, "undetermined");
  EXPECT_NE(find(claims, "delta/D falls").numbers.find("needs two finished cases"),
            std::string::npos);
  EXPECT_EQ(find(claims, "delta/D is nearly constant").verdict, "undetermined");
  EXPECT_EQ(find(claims, "the wake").verdict, "holds");
  t.rows.clear();
  EXPECT_EQ(find(check_paper_claims(t), "the wake").verdict, "undetermined");
}

}  // namespace
