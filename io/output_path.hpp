// Output paths checked before the work, not after: a command that writes files checks its folder
// or file first, so a bad path is one typed line at once instead of an error after minutes of work
// (or an error that names an internal temporary file).
#pragma once
#include <string>

namespace splinex {

/// What is wrong with writing a file at `path` (empty: nothing): not empty, not a folder, its
/// folder exists and is writable. Nothing is created.
std::string output_file_problem(const std::string& path);
/// What is wrong with writing into the folder `dir` (empty: nothing): not empty, not a file, and it
/// or its nearest existing parent is a writable folder. Nothing is created.
std::string output_folder_problem(const std::string& dir);

/// `dir` exists as a folder (created if missing) and a file can be written into it.
/// UsageError naming `field` otherwise (empty, a file in the way, no permission).
void prepare_output_folder(const std::string& dir, const std::string& field);

}  // namespace splinex
