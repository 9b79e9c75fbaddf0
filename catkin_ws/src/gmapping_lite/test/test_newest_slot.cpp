#include <gtest/gtest.h>

#include <thread>

#include "gmapping_lite/newest_slot.h"

namespace gmapping_lite {

TEST(NewestSlot, TheWorkerTakesTheNewestAndTheReplacedOnesCountAsSkipped) {
  NewestSlot<int> slot;
  slot.put(1);
  slot.put(2);
  slot.put(3);
  EXPECT_EQ(slot.take(), 3);
  EXPECT_EQ(slot.skipped(), 2u);
  slot.put(4);
  EXPECT_EQ(slot.take(), 4);
  EXPECT_EQ(slot.skipped(), 2u);
  EXPECT_EQ(slot.offered(), 4u);
}

TEST(NewestSlot, CloseWakesAWaitingWorker) {
  NewestSlot<int> slot;
  std::optional<int> got = 0;
  std::thread worker([&] { got = slot.take(); });
  slot.close();
  worker.join();
  EXPECT_FALSE(got.has_value());
}

TEST(NewestSlot, AnItemPutWhileTheWorkerWaitsIsTaken) {
  NewestSlot<int> slot;
  std::optional<int> got;
  std::thread worker([&] { got = slot.take(); });
  slot.put(7);
  worker.join();
  EXPECT_EQ(got, 7);
  EXPECT_EQ(slot.skipped(), 0u);
}

}  // namespace gmapping_lite
