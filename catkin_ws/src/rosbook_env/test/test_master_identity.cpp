// same_master: which (pid, /run_id) answers are the master the node registered with.
#include <gtest/gtest.h>

#include "rosbook_env/master_watch.h"

using rosbook_env::MasterIdentity;
using rosbook_env::same_master;

TEST(SameMaster, TheSameAnswerIsTheSameMaster) {
  EXPECT_TRUE(same_master({41, "run-a"}, {41, "run-a"}));
  EXPECT_TRUE(same_master({41, ""}, {41, ""}));  // rosmaster started alone never gets a /run_id
}

TEST(SameMaster, ARunIdSetAfterTheMasterFirstAnsweredIsTheSameMaster) {
  // roscore's roslaunch sets /run_id up to a poll (0.1 s) after rosmaster answers.
  EXPECT_TRUE(same_master({57, ""}, {57, "run-b"}));
}

TEST(SameMaster, ANewPidOrANewRunIdIsANewMaster) {
  EXPECT_FALSE(same_master({41, "run-a"}, {57, ""}));
  EXPECT_FALSE(same_master({41, "run-a"}, {57, "run-b"}));
  EXPECT_FALSE(same_master({41, ""}, {57, ""}));
  EXPECT_FALSE(same_master({41, "run-a"}, {41, "run-b"}));  // the same pid again (a container)
  EXPECT_FALSE(same_master({41, "run-a"}, {41, ""}));        // ... before its roslaunch set /run_id
}
