#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "yarn_tearing/core/model/fabric_spec.hpp"
#include "yarn_tearing/core/simulation/simulation_parameters.hpp"
#include "yarn_tearing/core/simulation/simulator.hpp"
#include "yarn_tearing/core/tearing/tear_event.hpp"

namespace yarn_tearing {

/// How a virtual trouser tear test (ISO 13937-2's geometry, drawn in the fabric's plane) is run:
/// the fabric is held along its first row (its own pins are replaced), a slit is cut up the middle
/// of the patch from its last row across `slit_rows` picks (the weft segment between warp yarns
/// ends/2 - 1 and ends/2), and the last row's two halves, the tongues, are drawn apart along the
/// weft, each at `speed`, for `duration`.
struct TrouserTearSetup {
  int slit_rows = 4;      ///< picks the slit crosses, counted from the last row [-], >= 1
  double speed = 0.05;    ///< speed of each tongue's grip along the weft [m/s], > 0
  double duration = 0.4;  ///< simulated time of the pull [s], > 0
};

/// One point of the force–extension curve, recorded every step.
struct TrouserTearSample {
  double extension = 0.0;  ///< separation of the two grips, twice one grip's travel [m]
  /// Force the tongues resist the pull with, along the weft, the mean of the two tongues' [N].
  double force = 0.0;
};

/// What a textile lab reports from a trouser tear test.
struct TrouserTearResult {
  std::vector<TrouserTearSample> curve;  ///< force–extension curve, one point per step
  std::vector<TearEvent> events;         ///< every segment torn, in order
  /// The force's peak before each tear [N]: its largest value in the steps after the previous
  /// step with a tear (or the start) and before the next one; none where two steps tear in a row
  /// (a tear's own step is left out: its grips' forces include the length stop's,
  /// doc/method.md, "Breaking-length stop").
  std::vector<double> peaks;
  double mean_peak = 0.0;    ///< mean of `peaks` [N] (0 when nothing tore)
  double peak_spread = 0.0;  ///< sample standard deviation of `peaks` [N] (0 below two peaks)
};

/// Runs the trouser tear test on `spec` with `parameters`; `observe`, when given, is called after
/// every step with the simulator (stability checks, recordings). Throws std::invalid_argument on
/// an invalid spec or setup.
TrouserTearResult runTrouserTear(const SimulationParameters& parameters, const FabricSpec& spec,
                                 const TrouserTearSetup& setup,
                                 const std::function<void(const Simulator&)>& observe = {});

}  // namespace yarn_tearing
