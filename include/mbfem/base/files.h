#ifndef mbfem_base_files_h
#define mbfem_base_files_h

#include <functional>
#include <ostream>
#include <string>

/**
 * @file
 * Files written whole or not at all, and the output folder: every area
 * that writes (results, contact problems, tables) goes through these, so
 * that a run stopped by an error leaves no half-written file.
 */

namespace mbfem
{
  /**
   * Writes @p content to @p path via a temporary file and a rename; on any
   * failure (a full disk, a folder that went away) the temporary file is
   * removed and the message names the file and the reason. Under mpirun
   * rank 0 writes, and its failure ends the run on every rank.
   */
  void
  write_file_atomically(const std::string &path, const std::string &content);

  /** write_file_atomically() on this rank alone. */
  void
  write_on_this_rank(const std::string &path, const std::string &content);

  /**
   * The same, with the content written by @p write straight into the
   * temporary file: a block's VTU file (12.7 MB on each beam of the
   * 6697-pair stacked model) is not held in memory, and not twice.
   */
  void
  write_on_this_rank(const std::string                         &path,
                     const std::function<void(std::ostream &)> &write);

  /**
   * Creates 'Output/Directory' (@p directory) if missing, or an error that
   * names it and the reason (not a folder, no permission, a path too long).
   */
  void
  create_output_directory(const std::string &directory);

  /** create_output_directory() on this rank alone. */
  void
  create_directory_on_this_rank(const std::string &directory);
} // namespace mbfem

#endif
