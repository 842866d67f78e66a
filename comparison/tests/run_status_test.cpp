// The backend and mutant statuses of results.json; expected values written out
// from docs/results-format.md.
#include "comparison/run_status.h"

#include <gtest/gtest.h>

namespace comparison {
namespace {

TEST(BackendStatus, NamesRoundTripAndUnknownNamesAreRejected) {
  EXPECT_EQ(backendStatusName(BackendStatus::Ran), "ran");
  EXPECT_EQ(backendStatusName(BackendStatus::NotSupported), "NotSupported");
  EXPECT_EQ(backendStatusName(BackendStatus::Error), "error");
  for (const BackendStatus status : {BackendStatus::Ran, BackendStatus::NotSupported, BackendStatus::Error})
    EXPECT_EQ(parseBackendStatus(backendStatusName(status)), status) << status;
  for (const char* name : {"", "Ran", "Error", "notsupported", "Pass", "not listed in backends"})
    EXPECT_FALSE(parseBackendStatus(name).has_value()) << "'" << name << "'";
}

TEST(BackendStatus, OnlyAnErrorFailsTheRun) {
  EXPECT_FALSE(isRunFailure(BackendStatus::Ran));
  EXPECT_FALSE(isRunFailure(BackendStatus::NotSupported));
  EXPECT_TRUE(isRunFailure(BackendStatus::Error));
  EXPECT_EQ(ciOutcome(BackendStatus::NotSupported), CiOutcome::Skipped);
  EXPECT_EQ(ciOutcome(BackendStatus::Error), CiOutcome::Error);
}

TEST(MutantStatus, NamesRoundTripAndUnknownNamesAreRejected) {
  EXPECT_EQ(mutantStatusName(MutantStatus::Killed), "killed");
  EXPECT_EQ(mutantStatusName(MutantStatus::Survived), "survived");
  EXPECT_EQ(mutantStatusName(MutantStatus::NotSupported), "NotSupported");
  EXPECT_EQ(mutantStatusName(MutantStatus::Crash), "Crash");
  EXPECT_EQ(mutantStatusName(MutantStatus::Timeout), "Timeout");
  EXPECT_EQ(mutantStatusName(MutantStatus::NotRun), "NotRun");
  for (const MutantStatus status : {MutantStatus::Killed, MutantStatus::Survived, MutantStatus::NotSupported,
                                    MutantStatus::Crash, MutantStatus::Timeout, MutantStatus::NotRun})
    EXPECT_EQ(parseMutantStatus(mutantStatusName(status)), status) << status;
  for (const char* name : {"", "Killed", "SURVIVED", "Fail", "Pass", "timeout"})
    EXPECT_FALSE(parseMutantStatus(name).has_value()) << "'" << name << "'";
}

TEST(MutantStatus, KilledPassesNotSupportedSkipsTheRestFail) {
  EXPECT_FALSE(isRunFailure(MutantStatus::Killed));
  EXPECT_FALSE(isRunFailure(MutantStatus::NotSupported));
  EXPECT_TRUE(isRunFailure(MutantStatus::Survived));
  EXPECT_TRUE(isRunFailure(MutantStatus::Crash));
  EXPECT_TRUE(isRunFailure(MutantStatus::Timeout));
  EXPECT_TRUE(isRunFailure(MutantStatus::NotRun));
  EXPECT_EQ(ciOutcome(MutantStatus::Killed), CiOutcome::Pass);
  EXPECT_EQ(ciOutcome(MutantStatus::NotSupported), CiOutcome::Skipped);
  EXPECT_EQ(ciOutcome(MutantStatus::Survived), CiOutcome::Failure);
  EXPECT_EQ(ciOutcome(MutantStatus::Crash), CiOutcome::Error);
  EXPECT_EQ(ciOutcome(MutantStatus::Timeout), CiOutcome::Error);
  EXPECT_EQ(ciOutcome(MutantStatus::NotRun), CiOutcome::Error);
}

}  // namespace
}  // namespace comparison
