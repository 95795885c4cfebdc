// One row of a run's time series (run.h5 /observables), sampled at the output interval.
#pragma once

namespace granshock {

struct TimeSeriesRow {
  long step = 0;
  double time = 0;            // s
  long particles = 0;         // present in the domain
  double kinetic_energy = 0;  // J (translational + rotational)
  double temperature = 0;     // mixture granular temperature, J (docs/fields.md, whole domain)
  long contacts = 0;
  long inserted = 0;        // cumulative since the start of the run
  long deleted_outlet = 0;  // cumulative, through y > L
  long deleted_inlet = 0;   // cumulative, through y < 0
};

}  // namespace granshock
