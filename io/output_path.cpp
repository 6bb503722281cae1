#include "io/output_path.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "base/errors.hpp"

namespace splinex {

namespace fs = std::filesystem;

namespace {
bool writable_folder(const fs::path& p) { return ::access(p.c_str(), W_OK | X_OK) == 0; }
}  // namespace

std::string output_file_problem(const std::string& path) {
  if (path.empty()) return "the file name is empty";
  std::error_code ec;
  if (fs::is_directory(path, ec)) return path + " is a folder, not a file";
  const fs::path parent = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
  if (!fs::is_directory(parent, ec)) return path + ": the folder " + parent.string() + " does not exist";
  if (!writable_folder(parent)) return path + ": the folder " + parent.string() + " is not writable";
  if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0) return path + ": the file is not writable";
  return "";
}

std::string output_folder_problem(const std::string& dir) {
  if (dir.empty()) return "the folder name is empty";
  std::error_code ec;
  fs::path p(dir);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) return dir + " is a file, not a folder";
  // The nearest existing parent must be a writable folder (create_directories makes the rest).
  fs::path q = p;
  while (!q.empty() && !fs::exists(q, ec)) q = q.has_parent_path() && q.parent_path() != q ? q.parent_path() : fs::path();
  if (q.empty()) q = ".";
  if (!fs::is_directory(q, ec)) return dir + ": " + q.string() + " is a file, not a folder";
  if (!writable_folder(q)) return dir + ": the folder " + q.string() + " is not writable";
  return "";
}

void prepare_output_folder(const std::string& dir, const std::string& field) {
  const std::string why = output_folder_problem(dir);
  if (!why.empty()) throw UsageError(field, why, "give a folder that can be written");
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw UsageError(field, dir + ": cannot create the folder (" + ec.message() + ")", "give a folder that can be written");
}

}  // namespace splinex
