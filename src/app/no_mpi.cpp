// joinCluster for an rt built without MPI (CMake found no MPI): always one process.
#include <cstdlib>
#include <string>

#include "core/error.h"
#include "core/single_process.h"

namespace rb {

std::unique_ptr<Cluster> joinCluster(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--mpi" || arg == "--resume")
            throw InputError(arg +
                             ": this rt was built without MPI; `make mpi` installs Open MPI "
                             "(openmpi-bin, libopenmpi-dev) and rebuilds rt with it");
    }
    // Started by mpirun as one of several ranks: each would render the whole image alone.
    for (const char* size : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* value = std::getenv(size); value && std::atoi(value) > 1)
            throw InputError(std::string("mpirun started ") + value +
                             " copies of an rt built without MPI; `make mpi` installs Open MPI "
                             "(openmpi-bin, libopenmpi-dev) and rebuilds rt with it");
    return std::make_unique<SingleProcess>();
}

}  // namespace rb
