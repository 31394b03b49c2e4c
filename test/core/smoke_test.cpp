#include <gtest/gtest.h>
#include "yarn_tearing/core/simulator.hpp"
TEST(Smoke, Builds) { EXPECT_TRUE(true); }
