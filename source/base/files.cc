#include <mbfem/base/files.h>
#include <mbfem/base/parallel.h>

#include <deal.II/base/exceptions.h>

#include <filesystem>
#include <fstream>

namespace mbfem
{
  using namespace dealii;

  void
  write_file_atomically(const std::string &path, const std::string &content)
  {
    // Every rank holds the results; rank 0 writes them, and a failure
    // there ends the run on every rank.
    Parallel::on_owner(MPI_COMM_WORLD, 0, [&]() {
      write_on_this_rank(path, content);
    });
  }



  void
  write_on_this_rank(const std::string &path, const std::string &content)
  {
    write_on_this_rank(path, [&](std::ostream &out) { out << content; });
  }



  void
  write_on_this_rank(const std::string                         &path,
                     const std::function<void(std::ostream &)> &write)
  {
    const std::string temporary = path + ".part";
    std::string       failure;
    std::error_code   ec;
    {
      std::ofstream out(temporary, std::ios::binary);
      if (!out.good())
        failure = "cannot be created";
      else
        {
          try
            {
              write(out);
            }
          catch (...)
            {
              // A writer that met a failed stream (deal.II's ExcIO) says
              // so below, naming the file; anything else goes on up.
              if (!out.fail())
                {
                  out.close();
                  std::filesystem::remove(temporary, ec);
                  throw;
                }
            }
          out.close();
          if (out.fail())
            failure = "could not be written whole (is the disk full?)";
        }
    }
    if (failure.empty())
      {
        std::filesystem::rename(temporary, path, ec);
        if (ec)
          failure = "could not be renamed to <" + path + ">: " + ec.message();
      }
    if (!failure.empty())
      {
        std::filesystem::remove(temporary, ec);
        AssertThrow(false,
                    ExcMessage("The output file <" + temporary + "> " +
                               failure +
                               ". The files written before it are "
                               "complete."));
      }
  }



  void
  create_output_directory(const std::string &directory)
  {
    Parallel::on_owner(MPI_COMM_WORLD, 0, [&]() {
      create_directory_on_this_rank(directory);
    });
  }



  void
  create_directory_on_this_rank(const std::string &directory)
  {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    AssertThrow(
      !ec && std::filesystem::is_directory(directory, ec),
      ExcMessage(
        "Cannot create the folder 'Output/Directory' = '" + directory + "': " +
        (ec ? ec.message() : std::string("a file of that name exists")) + "."));
  }
} // namespace mbfem
