#include "fe/penny_gap_mesh_internal.h"

#include "fe/boundary_ids.h"
#include "input/input_error.h"
#include "parallel/collective.h"
#include "parallel/interruption.h"
#include "parallel/memory_budget.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>

#include <gmsh.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace penny
{
  using namespace dealii;

  namespace
  {
    // The longest gmsh may mesh a .geo (a 2D mesh takes seconds; a .geo that
    // loops would otherwise hold the run forever).
    constexpr unsigned int gmsh_time_limit = 600; // s

    // What a child process running gmsh reports by its exit status.
    enum GmshStatus
    {
      meshed        = 0,
      failed        = 1,
      out_of_memory = 2,
      exited_early  = 3, // the .geo ended gmsh (Exit;) before penny wrote the mesh
    };

    // In a child process (which never returns): meshes the .geo with gmsh,
    // passing c, R and H as parser numbers (the .geo declares them with
    // DefineConstant), and writes the mesh to `msh_file`.
    [[noreturn]] void run_gmsh(const std::string &geo_file, const std::string &msh_file,
                               const GeometryParameters &geometry)
    {
      // An exit() inside gmsh runs this first, before the parent's destructors.
      std::atexit([]() { _exit(exited_early); });
      // gmsh 4.8 has no parser API: the numbers go in as command-line options.
      std::vector<std::string> arguments = {"gmsh"};
      for (const auto &[name, value] : {std::pair<std::string, double>{"c", geometry.gap_radius},
                                        {"R", geometry.domain_radius},
                                        {"H", geometry.domain_height}})
        {
          std::ostringstream number;
          number.precision(17);
          number << value;
          arguments.insert(arguments.end(), {"-setnumber", name, number.str()});
        }
      std::vector<char *> argv;
      for (auto &argument : arguments)
        argv.push_back(argument.data());
      try
        {
          gmsh::initialize(argv.size(), argv.data(), false);
          gmsh::option::setNumber("General.Verbosity", 1);
          gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
          gmsh::open(geo_file);
          gmsh::model::mesh::generate(2);
          gmsh::write(msh_file);
          gmsh::finalize();
        }
      catch (const std::bad_alloc &)
        {
          _exit(out_of_memory);
        }
      catch (...)
        {
          _exit(failed);
        }
      _exit(meshed);
    }

    // The last of gmsh's error messages ("Error   : ..."), if any.
    std::string gmsh_error(const std::string &log)
    {
      std::istringstream lines(log);
      std::string        line, error;
      while (std::getline(lines, line))
        if (line.rfind("Error", 0) == 0)
          error = line;
      return one_line(error);
    }

    // The .msh text of a .geo meshed by gmsh in a child process, so that a
    // .geo that ends in Exit, a crash of gmsh, or gmsh running out of memory
    // (its address space is bounded by what the run may use) ends the child,
    // not penny. Rank 0 meshes; every rank reads the same text.
    std::string mesh_geo_file(const std::string &geo_file, const GeometryParameters &geometry,
                              const MPI_Comm communicator)
    {
      std::string msh;
      run_on_rank_zero(communicator, [&]() {
        const std::string entry  = in_quotes(geo_file);
        std::string       folder = (std::filesystem::temp_directory_path() / "penny-gmsh-XXXXXX").string();
        if (!mkdtemp(folder.data()))
          throw std::runtime_error("mesh: could not create a temporary folder for gmsh: " +
                                   std::string(std::strerror(errno)));
        remove_on_interruption(folder);
        const std::filesystem::path msh_file = std::filesystem::path(folder) / "mesh.msh";
        const std::filesystem::path log_file = std::filesystem::path(folder) / "gmsh.log";
        // The child's address space: what it inherits, and what the run may use.
        const double limit = mapped_memory() + memory_share * available_memory().bytes;
        std::cout.flush();
        const pid_t parent = getpid();
        const pid_t child  = fork();
        if (child < 0)
          {
            const std::string reason = std::strerror(errno);
            std::error_code   ignored;
            std::filesystem::remove_all(folder, ignored);
            forget_on_interruption(folder);
            throw std::runtime_error("mesh: could not start gmsh: " + reason);
          }
        if (child == 0)
          {
            // The child dies with penny, and by Ctrl-C or kill as a program does.
            restore_interruption_signals();
            prctl(PR_SET_PDEATHSIG, SIGKILL);
            alarm(gmsh_time_limit);
            if (getppid() != parent)
              _exit(failed);
            const int log = open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
            dup2(log, STDOUT_FILENO);
            dup2(log, STDERR_FILENO);
            rlimit address_space;
            getrlimit(RLIMIT_AS, &address_space);
            address_space.rlim_cur = std::min(static_cast<double>(address_space.rlim_max), limit);
            setrlimit(RLIMIT_AS, &address_space);
            run_gmsh(geo_file, msh_file.string(), geometry);
          }
        int status = 0;
        while (waitpid(child, &status, 0) < 0 && errno == EINTR)
          ;
        std::ifstream      in(msh_file);
        std::ostringstream text;
        text << in.rdbuf();
        msh = text.str();
        std::ifstream      log_stream(log_file);
        std::ostringstream log;
        log << log_stream.rdbuf();
        const std::string error = gmsh_error(log.str());
        std::error_code   ignored;
        std::filesystem::remove_all(folder, ignored);
        forget_on_interruption(folder);

        // An exception escaping gmsh's own threads ends it with SIGABRT.
        if ((WIFEXITED(status) && WEXITSTATUS(status) == out_of_memory) ||
            log.str().find("std::bad_alloc") != std::string::npos)
          throw InputError(entry + ": gmsh ran out of memory (its limit: " +
                           std::to_string(static_cast<long long>(limit / (1 << 20))) +
                           " MiB of address space); a coarser mesh needs less");
        if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
          throw InputError(entry + ": gmsh did not finish within " + std::to_string(gmsh_time_limit) +
                           " s (does the .geo loop, or ask for a far finer mesh?)");
        if (WIFSIGNALED(status))
          throw InputError(entry + ": gmsh was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                           strsignal(WTERMSIG(status)) + ")" +
                           (WTERMSIG(status) == SIGKILL ? ", perhaps by the kernel for lack of memory" : ""));
        switch (WEXITSTATUS(status))
          {
          case meshed:
            break;
          case exited_early:
            throw InputError(entry + ": gmsh stopped before the mesh was written (does the .geo say Exit?)");
          default:
            throw InputError(entry + " could not be meshed by gmsh" + (error.empty() ? "" : ": " + error));
          }
        if (msh.empty())
          throw InputError(entry + ": gmsh wrote no mesh" + (error.empty() ? "" : ": " + error));
      });
      return dealii::Utilities::MPI::broadcast(communicator, msh, 0);
    }
  } // namespace

  namespace internal
  {
    void read_gmsh(Triangulation<2> &triangulation, const GeometryParameters &geometry,
                   const MeshParameters &mesh)
    {
      const std::string entry  = in_quotes(mesh.mesh_file);
      const bool        is_geo = std::filesystem::path(mesh.mesh_file).extension() == ".geo";
      try
        {
          // The stream reader takes boundary ids from the physical tags.
          std::istringstream geo_mesh(
              is_geo ? mesh_geo_file(mesh.mesh_file, geometry, triangulation.get_communicator()) : "");
          std::ifstream msh_file;
          if (!is_geo)
            msh_file.open(mesh.mesh_file);
          GridIn<2> grid_in(triangulation);
          grid_in.read_msh(is_geo ? static_cast<std::istream &>(geo_mesh) : msh_file);
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const ExceptionBase &exception)
        {
          throw InputError(entry +
                           " is not a readable 2D gmsh mesh of quadrilaterals: " + one_line(exception));
        }
      catch (const std::exception &)
        {
          throw InputError(entry + " is not a readable 2D gmsh mesh of quadrilaterals");
        }
      if (!triangulation.all_reference_cells_are_hyper_cube())
        throw InputError(entry +
                         " holds triangles; penny needs quadrilaterals (Mesh.RecombineAll = 1 in the .geo)");

      std::set<types::boundary_id> ids;
      for (const auto &face : triangulation.active_face_iterators())
        if (face->at_boundary())
          ids.insert(face->boundary_id());
      for (const auto id : {boundary_id::symmetry, boundary_id::gap_face, boundary_id::ligament})
        if (ids.count(id) == 0)
          throw InputError(entry + " lacks physical curve tag " + std::to_string(id) +
                           " (1 axis, 2 gap face, 3 ligament, 4 far boundary)");
    }
  } // namespace internal
} // namespace penny
