#pragma once
/// \file out_of_memory.hpp
/// What the program says when an allocation fails after all: a scene is checked against the machine's memory before
/// it is built (memory_estimate.hpp), but the estimate can be beaten (another process taking memory meanwhile, a
/// module's grid fields, output buffers). Instead of `error: std::bad_alloc`, or `terminate called after throwing
/// an instance of 'std::bad_alloc'` from a worker thread, the user reads what ran out and what to change.

#include <string>

namespace mpm::app {

/// The message for a std::bad_alloc (after "error: ").
std::string out_of_memory_message();

/// Installs a std::terminate handler: an exception that escapes a thread (TBB's workers, std::thread) prints
/// "error: " and its message (out_of_memory_message() for std::bad_alloc) and ends the program with exit status 1,
/// the status of main's internal errors.
void install_terminate_handler();

}  // namespace mpm::app
