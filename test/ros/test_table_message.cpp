// The table's outline as a message: every segment and pocket carried with its id, shape and place, the noses at
// their height and the pockets on the cloth.
#include <gtest/gtest.h>

#include "table_message.hpp"

namespace bsp = billiard_shot_planner;

TEST(TableMessage, CarriesEverySegmentAndPocketByIdAtItsHeight)
{
  const bsp::Table table;
  const bsp::TableOutline outline = bsp::tableOutline(table).value();
  const bsp::TableGeometry message = bsp::tableMessage(outline, table, "table", ros::Time(12.5));
  EXPECT_EQ(message.header.frame_id, "table");
  EXPECT_EQ(message.header.stamp, ros::Time(12.5));
  EXPECT_EQ(message.length, table.length);
  EXPECT_EQ(message.width, table.width);
  ASSERT_EQ(message.cushions.size(), outline.cushions.size());
  ASSERT_EQ(message.pockets.size(), 6u);
  for (std::size_t i = 0; i < outline.cushions.size(); ++i)
  {
    const bsp::NoseSegment& segment = outline.cushions[i];
    const bsp::CushionSegment& sent = message.cushions[i];
    EXPECT_EQ(sent.id, segment.id);
    EXPECT_EQ(sent.shape,
              segment.shape == bsp::NoseSegment::Shape::Arc ? bsp::CushionSegment::ARC : bsp::CushionSegment::LINE);
    EXPECT_EQ(sent.start.x, segment.start.x());
    EXPECT_EQ(sent.end.y, segment.end.y());
    EXPECT_EQ(sent.start.z, table.cushion_height);
    EXPECT_EQ(sent.radius, segment.radius);
    EXPECT_EQ(sent.sweep, segment.sweep);
  }
  for (std::size_t k = 0; k < outline.pockets.size(); ++k)
  {
    EXPECT_EQ(message.pockets[k].id, outline.pockets[k].id);
    EXPECT_EQ(message.pockets[k].drop_radius, outline.pockets[k].drop_radius);
    EXPECT_EQ(message.pockets[k].drop_centre.z, 0.0);
    EXPECT_EQ(message.pockets[k].axis.x, outline.pockets[k].axis.x());
  }
}

TEST(TableMessage, ACaromTableIsFourRailsWithoutPockets)
{
  bsp::Table table;
  table.pocket_layout = bsp::PocketLayout::None;
  table.pockets.clear();
  const bsp::TableGeometry message = bsp::tableMessage(bsp::tableOutline(table).value(), table, "table", ros::Time());
  EXPECT_EQ(message.cushions.size(), 4u);
  EXPECT_TRUE(message.pockets.empty());
}
