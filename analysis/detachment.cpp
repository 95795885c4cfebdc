#include "analysis/detachment.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "analysis/block_error.hpp"

namespace granshock {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kDefinitions = kFrontDefinitions.size();
using Fronts = std::array<FrontFix, kDefinitions>;

std::string in_d(double length, const FieldPhysics& phys) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g d", length / phys.d);
  return text;
}

// The fronts on one profile (pooled, one block, merged blocks or a resample) by every
// definition. A front within the rows that measured the upstream state does not count.
Fronts fronts_on(const BinSums& profile, const FieldPhysics& phys, const UpstreamValues& upstream,
                 int begin, int end, const DetachmentSearch& search) {
  const StagnationLine line = stagnation_line(profile, phys, search.mask);
  Fronts fronts;
  for (std::size_t k = 0; k < kDefinitions; ++k) {
    FrontFix f = locate_front(kFrontDefinitions[k], line, begin, end, upstream, search.rule);
    if (f.found && f.y < search.y_upstream_end) {
      f.found = false;
      f.why = "the front on the stagnation line (y = " + in_d(f.y, phys) +
              ") lies within the grid rows that measure the upstream state (below y = " +
              in_d(search.y_upstream_end, phys) + ")";
    }
    fronts[k] = f;
  }
  return fronts;
}

// The sample standard deviation of the finite values (NaN with fewer than 2).
double spread(const std::vector<double>& values) {
  const double se = block_standard_error(values);
  return se * std::sqrt(static_cast<double>(values.size()));
}

// The standard error of the per-group deltas (groups: single blocks or merged pairs), and
// the reason when fewer than 2 groups show a front.
struct GroupError {
  double error = kNaN, width_error = kNaN;
  std::vector<double> deltas, widths;  // per group, NaN where no front (widths: or no fit)
  int used = 0;
  std::string first_failure;
};

std::vector<double> finite_of(const std::vector<double>& values) {
  std::vector<double> finite;
  for (double v : values)
    if (std::isfinite(v)) finite.push_back(v);
  return finite;
}
}  // namespace

const Detachment& of(const Detachments& all, FrontDefinition definition) {
  for (const Detachment& d : all)
    if (d.definition == definition) return d;
  return all.front();
}

Detachments measure_detachments(const BinSums& profile, const FieldPhysics& phys,
                                const UpstreamValues& upstream, const DetachmentSearch& search) {
  Detachments out;
  for (std::size_t k = 0; k < kDefinitions; ++k) {
    Detachment& d = out[k];
    d.definition = kFrontDefinitions[k];
    d.y_shock = d.surface = d.delta = d.delta_over_d = d.delta_err = d.delta_over_d_err = kNaN;
    d.err_blocks = d.err_merged_pairs = d.err_bootstrap = kNaN;
    d.peak = d.threshold = kNaN;
    d.width = d.width_err = d.low = d.fit_end = kNaN;
  }
  if (!phys.obstacle) {
    for (Detachment& d : out) d.reason = d.err_reason = "the scene has no obstacle";
    return out;
  }
  const double diameter = phys.obstacle->width;  // D: the frontal width (docs/fields.md)
  const double surface = phys.obstacle->face;
  int begin = 0, end = 0;
  while (begin < profile.ny && profile.y_centre(begin) < search.y_begin) ++begin;
  while (end < profile.ny && profile.y_centre(end) < surface) ++end;

  const Fronts pooled = fronts_on(profile.pooled_blocks(), phys, upstream, begin, end, search);
  for (std::size_t k = 0; k < kDefinitions; ++k) {
    Detachment& d = out[k];
    const FrontFix& f = pooled[k];
    d.surface = surface;
    d.peak = f.peak;
    d.threshold = f.found ? f.threshold : kNaN;
    d.found = f.found;
    if (f.found) {
      d.width = f.width;
      d.low = f.low;
      d.fit_end = f.fit_end;
      d.y_shock = f.y;
      d.delta = surface - f.y;
      d.delta_over_d = d.delta / diameter;
    } else if (end - begin < 2) {
      d.reason = "the stagnation-line profile holds " + std::to_string(std::max(end - begin, 0)) +
                 " bins between the search start (y = " + in_d(search.y_begin, phys) +
                 ") and the surface (y = " + in_d(surface, phys) + "); a front needs 2";
    } else {
      d.reason = "no shock front on the stagnation line: " + f.why;
    }
  }

  // Groups of `size` neighbouring blocks, each group with samples: their deltas and the
  // standard error of their mean.
  auto group_errors = [&](int size) {
    std::array<GroupError, kDefinitions> g;
    for (int b = 0; b + size <= profile.blocks; b += size) {
      const BinSums group = profile.block_range(b, b + size);
      if (!(group.total_samples() > 0)) continue;  // blocks the run never reached
      const Fronts f = fronts_on(group.pooled_blocks(), phys, upstream, begin, end, search);
      for (std::size_t k = 0; k < kDefinitions; ++k) {
        g[k].deltas.push_back(f[k].found ? surface - f[k].y : kNaN);
        g[k].widths.push_back(f[k].found ? f[k].width : kNaN);
        if (!f[k].found && g[k].first_failure.empty())
          g[k].first_failure =
              (size == 1 ? "block " : "blocks from ") + std::to_string(b) + ": " + f[k].why;
      }
    }
    for (GroupError& e : g) {
      const std::vector<double> finite = finite_of(e.deltas);
      e.used = static_cast<int>(finite.size());
      e.error = block_standard_error(finite);
      e.width_error = block_standard_error(finite_of(e.widths));
    }
    return g;
  };
  const std::array<GroupError, kDefinitions> single = group_errors(1), pairs = group_errors(2);

  // Bootstrap: the blocks with samples drawn with replacement, pooled, searched again. The
  // seed is fixed so that an analysis is reproducible.
  std::vector<int> sampled;
  for (int b = 0; b < profile.blocks; ++b)
    if (profile.samples[static_cast<std::size_t>(b)] > 0) sampled.push_back(b);
  std::array<std::vector<double>, kDefinitions> resampled, resampled_widths;
  const int resamples = sampled.size() >= 2 ? search.bootstrap_resamples : 0;
  std::mt19937_64 rng(20261123);
  std::uniform_int_distribution<std::size_t> pick(0, sampled.empty() ? 0 : sampled.size() - 1);
  for (int r = 0; r < resamples; ++r) {
    std::vector<int> weights(static_cast<std::size_t>(profile.blocks), 0);
    for (std::size_t i = 0; i < sampled.size(); ++i)
      ++weights[static_cast<std::size_t>(sampled[pick(rng)])];
    const Fronts f =
        fronts_on(profile.weighted_blocks(weights), phys, upstream, begin, end, search);
    for (std::size_t k = 0; k < kDefinitions; ++k)
      if (f[k].found) {
        resampled[k].push_back(surface - f[k].y);
        resampled_widths[k].push_back(f[k].width);
      }
  }

  for (std::size_t k = 0; k < kDefinitions; ++k) {
    Detachment& d = out[k];
    d.delta_blocks = single[k].deltas;
    d.blocks_used = single[k].used;
    d.err_blocks = single[k].error;
    d.err_merged_pairs = pairs[k].error;
    d.bootstrap_resamples = resamples;
    d.bootstrap_found = static_cast<int>(resampled[k].size());
    // A bootstrap in which a front is often missing says the front is not resolved in
    // the data: its spread would describe only the lucky resamples.
    if (resamples > 0 && 10 * d.bootstrap_found >= 9 * resamples)
      d.err_bootstrap = spread(resampled[k]);
    if (!d.found) {
      d.err_reason = "delta/D itself is undeterminable";
      continue;
    }
    // The blocks' own spread, from merged pairs where there are two (so that correlated
    // neighbours raise it), raised to the bootstrap's where that is larger.
    const double from_blocks =
        std::isfinite(d.err_merged_pairs) ? d.err_merged_pairs : d.err_blocks;
    if (!std::isfinite(from_blocks)) {
      d.err_reason = "only " + std::to_string(d.blocks_used) + " of the " +
                     std::to_string(d.delta_blocks.size()) +
                     " blocks with samples show a front on the stagnation line (the error needs 2)";
      if (!single[k].first_failure.empty()) d.err_reason += "; " + single[k].first_failure;
      continue;
    }
    d.delta_err =
        std::isfinite(d.err_bootstrap) ? std::max(from_blocks, d.err_bootstrap) : from_blocks;
    // The steepest rise sits on a pair's midpoint unless the parabola refines it: on
    // coarse rows every resample can give the same midpoint, a spread of zero that says
    // nothing. Its error is at least that of a position known to one row, dy / sqrt(12).
    if (d.definition == FrontDefinition::density_max_gradient)
      d.delta_err = std::max(d.delta_err, profile.dy / std::sqrt(12.0));
    d.delta_over_d_err = d.delta_err / diameter;
    // The thickness's error by the same rule as delta's.
    if (std::isfinite(d.width)) {
      const double width_blocks =
          std::isfinite(pairs[k].width_error) ? pairs[k].width_error : single[k].width_error;
      const double width_bootstrap =
          std::isfinite(d.err_bootstrap) ? spread(finite_of(resampled_widths[k])) : kNaN;
      d.width_err =
          std::isfinite(width_bootstrap) ? std::max(width_blocks, width_bootstrap) : width_blocks;
    }
  }
  return out;
}

Detachment measure_detachment(const BinSums& profile, const FieldPhysics& phys,
                              const UpstreamValues& upstream, const DetachmentSearch& search,
                              FrontDefinition definition) {
  return of(measure_detachments(profile, phys, upstream, search), definition);
}

Detachment measure_detachment(const BinSums& profile, const FieldPhysics& phys, double phi_up,
                              double y_search_begin, const ThresholdRule& rule) {
  DetachmentSearch search;
  search.y_begin = y_search_begin;
  search.rule = rule;
  return measure_detachment(profile, phys, UpstreamValues{phi_up}, search,
                            FrontDefinition::density_threshold);
}

}  // namespace granshock
