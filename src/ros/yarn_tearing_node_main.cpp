// yarn_tearing_node: the tearable-yarn simulator (see YarnTearingNode). Exit status: 0 after a
// normal shutdown, 1 for an invalid configuration, 2 when the simulation failed (NodeExitStatus).
#include "yarn_tearing/ros/node_runner.hpp"

int main(int argc, char** argv) { return yarn_tearing::ros_layer::runYarnTearingNode(argc, argv); }
