// The statuses beside the verdicts in results.json (docs/results-format.md):
// a backend's in a run, and a mutant's on a backend. Like verdict.h, the one
// place their names and meanings are written; the runner writes them and the
// reports read them back.
#pragma once

#include "comparison/verdict.h"

#include <optional>
#include <ostream>
#include <string_view>

namespace comparison {

// Ran: its backend came up (its tests have verdicts of their own).
// NotSupported: not present here, a skip. Error: present, but it broke.
enum class BackendStatus { Ran, NotSupported, Error };

std::string_view backendStatusName(BackendStatus status);  // "ran" | "NotSupported" | "error"
std::optional<BackendStatus> parseBackendStatus(std::string_view name);
std::ostream& operator<<(std::ostream& out, BackendStatus status);

// Killed: at least one scene that passes without the mutant failed with it.
// Crash and Timeout: its run did not finish, so it proves nothing; NotRun:
// an interrupted run stopped before its scenes were checked, likewise.
enum class MutantStatus { Killed, Survived, NotSupported, Crash, Timeout, NotRun };

std::string_view mutantStatusName(MutantStatus status);  // "killed" | "survived" | "NotSupported" | ...
std::optional<MutantStatus> parseMutantStatus(std::string_view name);
std::ostream& operator<<(std::ostream& out, MutantStatus status);

// An admissible variant (SPEC 7) on a backend, over its tests. Sound: every
// scene passed (or failed as its expected-failures line says). Unsound: some
// scene failed, a fault of lightcts (or of the driver, then listed).
// Incomplete: some test crashed, timed out or was not run, so it proves nothing.
// NotSupported: the backend is not present.
enum class AdmissibleStatus { Sound, Unsound, Incomplete, NotSupported };

std::string_view admissibleStatusName(AdmissibleStatus status);  // "sound" | "unsound" | "incomplete" | "NotSupported"
std::optional<AdmissibleStatus> parseAdmissibleStatus(std::string_view name);
std::ostream& operator<<(std::ostream& out, AdmissibleStatus status);

// A status that makes `lightcts run` exit 1: a backend Error; a mutant that
// Survived, Crashed, Timed out or was not run; an admissible variant Unsound or Incomplete.
bool isRunFailure(BackendStatus status);
bool isRunFailure(MutantStatus status);

// What it means to CI: Ran and Killed pass, NotSupported is a skip, a
// backend Error and a mutant's Crash, Timeout or NotRun are errors, Survived fails.
CiOutcome ciOutcome(BackendStatus status);
CiOutcome ciOutcome(MutantStatus status);

}  // namespace comparison
