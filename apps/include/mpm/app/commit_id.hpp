#pragma once
/// \file commit_id.hpp
/// The source version the program was built from, for the self-describing output files.

namespace mpm::app {

/// `git describe --always --dirty` of the source tree at build time ("abc123def456-dirty"), or "unknown"
/// when it was not built from a git checkout. Generated (apps/write_commit_id.cmake).
const char* commit_id();

}  // namespace mpm::app
