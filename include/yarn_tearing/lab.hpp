/// The virtual lab in one include: the single-end tensile pull, the trouser tear and the stiff
/// reference yarn, experiments run on the simulation core. Link yarn_tearing_lab.
#pragma once

#include "yarn_tearing/core/lab/stiff_reference_yarn.hpp"
#include "yarn_tearing/core/lab/tensile_pull.hpp"
#include "yarn_tearing/core/lab/trouser_tear.hpp"
