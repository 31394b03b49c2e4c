#pragma once

#include <cstddef>

#include "yarn_tearing/ros/input_bounds.hpp"

namespace yarn_tearing {
namespace ros_layer {

/// Physical bounds on the node's parameters (doc/node.md, "Bad input"): what the simulation can
/// represent in double precision with room to spare. A parameter past one stops the node at start,
/// naming the parameter and the bound.
namespace parameter_bounds {

constexpr double kMaxGravity = 1.0e3;                        ///< |gravity| [m/s^2] (100 g)
constexpr double kMaxPosition = input_bounds::kMaxDistance;  ///< yarn ends from the origin [m]
constexpr double kMinRadius = 1.0e-7;         ///< yarn radius [m] (a fine fibre is 5e-6)
constexpr double kMaxRadius = 1.0;            ///< yarn radius [m]
constexpr double kMinTex = 1.0e-3;            ///< linear density [g/km]
constexpr double kMaxTex = 1.0e7;             ///< linear density [g/km] (10 kg/m)
constexpr double kMaxLength = 1.0e4;          ///< yarn length [m]
constexpr double kMinSegment = 1.0e-6;        ///< length / (num_vertices - 1) [m]
constexpr double kMinDensity = 1.0;           ///< material density [kg/m^3]
constexpr double kMaxDensity = 1.0e5;         ///< material density [kg/m^3]
constexpr double kMaxCurveStrain = 10.0;      ///< strain of a stress-strain point [-]
constexpr double kMaxCurveStress = 1.0e12;    ///< stress of a stress-strain point [Pa]
constexpr double kMinYoungsModulus = 1.0e3;   ///< slope of the first curve segment [Pa]
constexpr double kMaxYoungsModulus = 1.0e13;  ///< slope of the first curve segment [Pa]
constexpr double kMaxEndMass = 1.0e3;         ///< end_mass [kg]
constexpr double kMinDirection = 1.0e-6;      ///< |direction| [-]
constexpr double kMaxDirection = 1.0e6;       ///< |direction| [-]
constexpr double kMaxWeibullModulus = 1.0e3;  ///< weibull_modulus [-] (0 = none, else >= 1)
constexpr double kMaxFrameTimeout = 1.0e6;    ///< frame_timeout [s]
constexpr double kMaxRealTimeFactor = 1.0e3;  ///< real_time_factor [-] (0 = as fast as possible)
constexpr double kMinPublishRate = 1.0e-3;    ///< publish_rate [Hz]
constexpr double kMaxPublishRate = 1.0e3;     ///< publish_rate [Hz]
constexpr double kMaxExtrapolation = 10.0;    ///< max_extrapolation [s]
constexpr int kMaxYarnVertices = 100000;     ///< num_vertices of one yarn (ends, picks of a fabric)
constexpr double kMaxShearRigidity = 1.0e6;  ///< a fabric's shear_rigidity [N/m]
constexpr double kMinObstacleSize = 1.0e-6;  ///< an obstacle's radius, half length, half extent [m]
constexpr double kMaxObstacleSize = 1.0e4;   ///< the same, at most [m] (as the core)
constexpr double kMaxFriction = 10.0;  ///< an obstacle's friction coefficient [-] (as the core)
/// Vertices plus edges over all yarns and fabrics: checked before anything is allocated. At the
/// budget, yarns hanging from pins step in about 0.3 s and hold about 0.5 GB (doc/node.md).
constexpr std::size_t kSceneBudget = 1000000;
/// Vertices over all fabrics, whose steps solve coupled grids: 256 x 256 steps in about 0.2 s
/// while falling and holds about 0.5 GB, as the yarns at kSceneBudget (doc/node.md).
constexpr std::size_t kFabricVertexBudget = 65536;

}  // namespace parameter_bounds

}  // namespace ros_layer
}  // namespace yarn_tearing
