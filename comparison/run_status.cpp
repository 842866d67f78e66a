#include "comparison/run_status.h"

#include <array>
#include <stdexcept>

namespace comparison {
namespace {

constexpr std::array kBackendStatuses = {BackendStatus::Ran, BackendStatus::NotSupported, BackendStatus::Error};
constexpr std::array kMutantStatuses = {MutantStatus::Killed, MutantStatus::Survived, MutantStatus::NotSupported,
                                        MutantStatus::Crash, MutantStatus::Timeout, MutantStatus::NotRun};

constexpr std::array kAdmissibleStatuses = {AdmissibleStatus::Sound, AdmissibleStatus::Unsound,
                                            AdmissibleStatus::Incomplete, AdmissibleStatus::NotSupported};

}  // namespace

std::string_view backendStatusName(BackendStatus status) {
  switch (status) {
    case BackendStatus::Ran: return "ran";
    case BackendStatus::NotSupported: return "NotSupported";
    case BackendStatus::Error: return "error";
  }
  throw std::invalid_argument("backendStatusName: not a BackendStatus");
}

std::optional<BackendStatus> parseBackendStatus(std::string_view name) {
  for (const BackendStatus status : kBackendStatuses)
    if (backendStatusName(status) == name) return status;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, BackendStatus status) { return out << backendStatusName(status); }

std::string_view mutantStatusName(MutantStatus status) {
  switch (status) {
    case MutantStatus::Killed: return "killed";
    case MutantStatus::Survived: return "survived";
    // The same words as the verdicts they come from.
    case MutantStatus::NotSupported: return verdictName(Verdict::NotSupported);
    case MutantStatus::Crash: return verdictName(Verdict::Crash);
    case MutantStatus::Timeout: return verdictName(Verdict::Timeout);
    case MutantStatus::NotRun: return verdictName(Verdict::NotRun);
  }
  throw std::invalid_argument("mutantStatusName: not a MutantStatus");
}

std::optional<MutantStatus> parseMutantStatus(std::string_view name) {
  for (const MutantStatus status : kMutantStatuses)
    if (mutantStatusName(status) == name) return status;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, MutantStatus status) { return out << mutantStatusName(status); }

std::string_view admissibleStatusName(AdmissibleStatus status) {
  switch (status) {
    case AdmissibleStatus::Sound: return "sound";
    case AdmissibleStatus::Unsound: return "unsound";
    case AdmissibleStatus::Incomplete: return "incomplete";
    case AdmissibleStatus::NotSupported: return verdictName(Verdict::NotSupported);
  }
  throw std::invalid_argument("admissibleStatusName: not an AdmissibleStatus");
}

std::optional<AdmissibleStatus> parseAdmissibleStatus(std::string_view name) {
  for (const AdmissibleStatus status : kAdmissibleStatuses)
    if (admissibleStatusName(status) == name) return status;
  return std::nullopt;
}

std::ostream& operator<<(std::ostream& out, AdmissibleStatus status) { return out << admissibleStatusName(status); }

// Switches without a default, as in verdict.cpp: -Wswitch names each of
// them when a status is added.
bool isRunFailure(BackendStatus status) {
  switch (status) {
    case BackendStatus::Ran:
    case BackendStatus::NotSupported: return false;
    case BackendStatus::Error: return true;
  }
  return true;
}

bool isRunFailure(MutantStatus status) {
  switch (status) {
    case MutantStatus::Killed:
    case MutantStatus::NotSupported: return false;
    case MutantStatus::Survived:
    case MutantStatus::Crash:
    case MutantStatus::Timeout:
    case MutantStatus::NotRun: return true;
  }
  return true;
}

CiOutcome ciOutcome(BackendStatus status) {
  switch (status) {
    case BackendStatus::Ran: return CiOutcome::Pass;
    case BackendStatus::NotSupported: return CiOutcome::Skipped;
    case BackendStatus::Error: return CiOutcome::Error;
  }
  return CiOutcome::Error;
}

CiOutcome ciOutcome(MutantStatus status) {
  switch (status) {
    case MutantStatus::Killed: return CiOutcome::Pass;
    case MutantStatus::NotSupported: return CiOutcome::Skipped;
    case MutantStatus::Crash:
    case MutantStatus::Timeout:
    case MutantStatus::NotRun: return CiOutcome::Error;
    case MutantStatus::Survived: return CiOutcome::Failure;
  }
  return CiOutcome::Failure;
}

}  // namespace comparison
