/* Measurement only (issue 30, doc/parallel.md "Why the jointed slope does
 * not gain from ranks"): one analysis, five factorisations and solves of a
 * sparse matrix with MUMPS on MPI_COMM_WORLD, the matrix given on rank 0.
 *
 * Input: a text file "n nnz" then nnz lines "r j value" meaning A(j, r) =
 * value (the compressed columns of A^T that SparseLU hands to UMFPACK,
 * written from SparseLU::factorize() by a temporary patch, doc/parallel.md).
 *
 *   mpicc -O2 -o mumps_interface_system benchmarks/mumps_interface_system.c \
 *         -ldmumps -lmumps_common
 *   OPENBLAS_NUM_THREADS=1 mpirun -np 1 ./mumps_interface_system A.txt
 *   OPENBLAS_NUM_THREADS=1 mpirun -np 2 ./mumps_interface_system A.txt
 */
#include <dmumps_c.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  int rank; MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  DMUMPS_STRUC_C id = {0};
  id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(MPI_COMM_WORLD);
  id.par = 1; id.sym = 0; id.job = -1;
  dmumps_c(&id);
  long n = 0, nnz = 0; int *irn = 0, *jcn = 0; double *a = 0, *rhs = 0;
  if (rank == 0)
    {
      FILE *f = fopen(argv[1], "r");
      if (fscanf(f, "%ld %ld", &n, &nnz) != 2) return 1;
      irn = malloc(nnz * sizeof(int)); jcn = malloc(nnz * sizeof(int));
      a = malloc(nnz * sizeof(double)); rhs = malloc(n * sizeof(double));
      for (long k = 0; k < nnz; ++k)
        { long r, j; double v;
          if (fscanf(f, "%ld %ld %lf", &r, &j, &v) != 3) return 1;
          irn[k] = j + 1; jcn[k] = r + 1; a[k] = v; }
      fclose(f);
      id.n = n; id.nnz = nnz; id.irn = irn; id.jcn = jcn; id.a = a; id.rhs = rhs;
    }
  id.icntl[0] = -1; id.icntl[1] = -1; id.icntl[2] = -1; id.icntl[3] = 0;
  id.icntl[6] = 5; /* METIS */
  const int reps = 5; double tf = 0, ts = 0, ta = 0;
  id.job = 1; MPI_Barrier(MPI_COMM_WORLD); double t0 = MPI_Wtime();
  dmumps_c(&id); MPI_Barrier(MPI_COMM_WORLD); ta = MPI_Wtime() - t0;
  for (int k = 0; k < reps; ++k)
    {
      id.job = 2; MPI_Barrier(MPI_COMM_WORLD); t0 = MPI_Wtime();
      dmumps_c(&id); MPI_Barrier(MPI_COMM_WORLD); tf += MPI_Wtime() - t0;
      if (id.infog[0] < 0) { if (rank == 0) printf("INFOG(1) = %d\n", id.infog[0]); break; }
      if (rank == 0) for (long i = 0; i < n; ++i) rhs[i] = 1. + i % 7;
      id.job = 3; MPI_Barrier(MPI_COMM_WORLD); t0 = MPI_Wtime();
      dmumps_c(&id); MPI_Barrier(MPI_COMM_WORLD); ts += MPI_Wtime() - t0;
    }
  int size; MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank == 0)
    printf("MUMPS 5.5, %d process(es), n = %ld: analysis %.1f ms, factorisation %.1f ms, solve %.2f ms\n",
           size, n, 1e3 * ta, 1e3 * tf / reps, 1e3 * ts / reps);
  id.job = -2; dmumps_c(&id);
  MPI_Finalize();
  return 0;
}
