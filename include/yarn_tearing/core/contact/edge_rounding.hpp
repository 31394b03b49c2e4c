#pragma once

#include "yarn_tearing/core/contact/obstacle.hpp"

namespace yarn_tearing {

/// A box's edges and corners as a yarn's contact sees them (doc/method.md, "Rounded box edges"). A
/// chain of straight segments bent over a sharp edge turns at one vertex and cogs there: its two
/// chords' pushes balance tension ratios up to 1/cos(theta) without any friction. Rounded to a
/// radius the mesh resolves, the bend spreads over several chords and a frictionless edge passes
/// the tension on, as a capstan post does. The yarn's centre line then stays on a fillet of
/// radius rho_e = max(edge_radius + r, kEdgeRoundingChords h) about the edge (h the segment's
/// rest length, r the yarn's radius); the faces stay where they are.

/// Segment lengths a box's edge is rounded to for the contact [-]: rho_e >= this times h.
/// Measured (test/core/box_edge_test.cpp): at 1 h the 60-degree ridge still cogs, from 2 h on
/// the frictionless Atwood machine over it moves as its closed form.
constexpr double kEdgeRoundingChords = 2.0;

/// The rounding [m] by which a yarn of radius `yarn_radius` [m] and segments of rest length
/// `segment_length` [m] sees the edges of `obstacle` rounded beyond its own radius: rho_e - r
/// (Obstacle::signedDistance's `rounding`). 0 for every shape but a box.
double contactRounding(const Obstacle& obstacle, double yarn_radius, double segment_length);

}  // namespace yarn_tearing
