// Latency and bandwidth between two ranks (the link figures of the cost model, docs/distributed.md).
// Rank 0 sends a message of n bytes to rank 1, which sends it back; half the mean round trip is the one-way time.
//   mpirun --oversubscribe -np 2 build/bench/bench_pingpong [--repeat N]
// Prints, per size, the one-way time and the bandwidth, then the model's t(n) = latency + n / bandwidth: the
// latency is the one-way time of 8 B, the bandwidth that of the largest message less the latency (a least-squares
// fit over all sizes is dominated by the large messages and can give a negative latency).
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int repeat = 200;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0) repeat = std::atoi(argv[i + 1]);
  if (size < 2 || repeat < 1) {
    if (rank == 0) std::fprintf(stderr, "bench_pingpong: needs 2 ranks (mpirun -np 2) and --repeat >= 1\n");
    MPI_Finalize();
    return 2;
  }
  std::vector<char> buffer(16 << 20);
  double latency = 0, largest = 0, largest_time = 0;
  if (rank == 0) std::printf("%12s %14s %14s\n", "bytes", "one-way (us)", "MB/s");
  for (std::size_t n = 8; n <= buffer.size(); n *= 4) {
    const int rounds = n >= (1u << 20) ? std::max(5, repeat / 20) : repeat;
    MPI_Barrier(MPI_COMM_WORLD);
    const double start = MPI_Wtime();
    for (int r = 0; r < rounds; ++r) {
      if (rank == 0) {
        MPI_Send(buffer.data(), static_cast<int>(n), MPI_CHAR, 1, 0, MPI_COMM_WORLD);
        MPI_Recv(buffer.data(), static_cast<int>(n), MPI_CHAR, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      } else if (rank == 1) {
        MPI_Recv(buffer.data(), static_cast<int>(n), MPI_CHAR, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        MPI_Send(buffer.data(), static_cast<int>(n), MPI_CHAR, 0, 0, MPI_COMM_WORLD);
      }
    }
    const double one_way = (MPI_Wtime() - start) / rounds / 2;
    if (rank == 0) {
      std::printf("%12zu %14.3f %14.1f\n", n, one_way * 1e6, static_cast<double>(n) / one_way / 1e6);
      if (n == 8) latency = one_way;
      largest = static_cast<double>(n);
      largest_time = one_way;
    }
  }
  if (rank == 0) {
    std::printf("model: latency %.3f us (8 B), bandwidth %.1f MB/s (%.0f B; t = latency + bytes / bandwidth)\n",
                latency * 1e6, largest / (largest_time - latency) / 1e6, largest);
  }
  MPI_Finalize();
  return 0;
}
