// Reading an error's field path: the element of a list a field starts with, and what lies under a name.
#include <gtest/gtest.h>

#include "billiard_shot_planner/core/error_fields.hpp"

namespace bsp = billiard_shot_planner;

TEST(ErrorFields, TheElementOfAListAndTheRest)
{
  const auto other = bsp::elementOf("others[12].position", "others");
  ASSERT_TRUE(other);
  EXPECT_EQ(other->index, 12u);
  EXPECT_EQ(other->rest, ".position");
  EXPECT_EQ(bsp::elementOf("shots[0]", "shots")->rest, "");
  for (const char* field : {"others[x].position", "others[].a", "others[3", "balls[1]", "others", "others[-1]"})
    EXPECT_FALSE(bsp::elementOf(field, "others")) << field;
}

TEST(ErrorFields, WhatLiesUnderAName)
{
  EXPECT_EQ(bsp::restUnder("cue.ball", "cue.ball"), std::string());
  EXPECT_EQ(bsp::restUnder("cue.ball.x", "cue.ball"), std::string(".x"));
  EXPECT_EQ(bsp::restUnder("tracks.cue[3].t", "tracks.cue"), std::string("[3].t"));
  EXPECT_FALSE(bsp::restUnder("cue.balls", "cue.ball"));
  EXPECT_FALSE(bsp::restUnder("tracks.cue2[0]", "tracks.cue"));
  EXPECT_FALSE(bsp::restUnder("ball", "cue.ball"));
}
