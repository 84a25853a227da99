#include <mbfem/linear_algebra/sparse_lu.h>

#include <deal.II/base/exceptions.h>

#include <metis.h>
#include <umfpack.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

namespace mbfem
{
  namespace
  {
    /** UMFPACK's defaults, with @p ordering. */
    std::array<double, UMFPACK_CONTROL>
    control(const SparseLU::Ordering ordering)
    {
      std::array<double, UMFPACK_CONTROL> c;
      umfpack_dl_defaults(c.data());
      c[UMFPACK_ORDERING] = ordering == SparseLU::Ordering::metis ?
                              UMFPACK_ORDERING_METIS :
                              UMFPACK_ORDERING_AMD;
      return c;
    }

    /**
     * The graph that nested_dissection() orders: the columns of a matrix
     * in compressed columns that are not singletons, a block of them (a
     * pair's directions) one vertex, adjacent where they share a row.
     */
    struct ColumnGraph
    {
      /** Singleton columns, and the rows pivoted with them. */
      std::vector<bool> column_out, row_out;
      /** Vertex v: rows rows[row_start[v]] ..., columns from first_column[v].
       */
      std::vector<long> rows, row_start{0}, first_column;
      /** Each vertex's number of columns (METIS's vertex weights). */
      std::vector<idx_t> weights;
      /** The adjacency in METIS's compressed form. */
      std::vector<idx_t> offsets{0}, neighbours;
    };



    /**
     * Singletons, one pass: a column with one entry, or a row with one, is
     * pivoted on first with its row or column (UMFPACK does so itself).
     */
    void
    mark_singletons(const long               n,
                    const std::vector<long> &start,
                    const std::vector<long> &index,
                    ColumnGraph             &graph)
    {
      std::vector<unsigned int> row_count(n, 0);
      for (long p = 0; p < start[n]; ++p)
        ++row_count[index[p]];
      graph.column_out.assign(n, false);
      graph.row_out.assign(n, false);
      for (long j = 0; j < n; ++j)
        if (start[j + 1] - start[j] == 1)
          {
            graph.column_out[j]            = true;
            graph.row_out[index[start[j]]] = true;
          }
      for (long j = 0; j < n; ++j)
        for (long p = start[j]; p < start[j + 1]; ++p)
          if (row_count[index[p]] == 1 && !graph.row_out[index[p]])
            {
              graph.row_out[index[p]] = true;
              graph.column_out[j]     = true;
            }
    }



    /**
     * The vertices: each block of @p block_size columns among the first
     * @p n_blocked (else each column) that is not all singletons, with the
     * blocks of its columns' remaining rows, blocked in the same way.
     */
    void
    merge_blocks(const long               n,
                 const std::vector<long> &start,
                 const std::vector<long> &index,
                 const unsigned int       block_size,
                 const unsigned int       n_blocked,
                 ColumnGraph             &graph)
    {
      // Rows in blocks too: the graph's cost is its entries times the
      // vertices in a row (some 0.1 s a factorisation on the cube with
      // the rows alone).
      const long n_blocks = (n_blocked + block_size - 1) / block_size;
      const auto block_of = [&](const long i) {
        return i < n_blocked ? i / block_size : n_blocks + (i - n_blocked);
      };
      auto &rows = graph.rows;
      for (long j = 0; j < n;)
        {
          const long end =
            j < n_blocked ?
              std::min<long>(j - j % block_size + block_size, n_blocked) :
              j + 1;
          const std::size_t first_row = rows.size();
          idx_t             members   = 0;
          for (long c = j; c < end; ++c)
            if (!graph.column_out[c])
              {
                ++members;
                for (long p = start[c]; p < start[c + 1]; ++p)
                  if (!graph.row_out[index[p]])
                    rows.push_back(block_of(index[p]));
              }
          if (members > 0)
            {
              std::sort(rows.begin() + first_row, rows.end());
              rows.erase(std::unique(rows.begin() + first_row, rows.end()),
                         rows.end());
              graph.row_start.push_back(rows.size());
              graph.first_column.push_back(j);
              graph.weights.push_back(members);
            }
          j = end;
        }
    }



    /** The vertices adjacent to each: those that share one of its rows. */
    void
    connect(const long n, ColumnGraph &graph)
    {
      const idx_t        n_vertices = graph.weights.size();
      const auto        &rows       = graph.rows;
      std::vector<long>  vertex_start(n + 1, 0);
      std::vector<idx_t> vertices_of_row(rows.size());
      for (const long i : rows)
        ++vertex_start[i + 1];
      std::partial_sum(vertex_start.begin(),
                       vertex_start.end(),
                       vertex_start.begin());
      std::vector<long> next(vertex_start.begin(), vertex_start.end() - 1);
      for (idx_t v = 0; v < n_vertices; ++v)
        for (long p = graph.row_start[v]; p < graph.row_start[v + 1]; ++p)
          vertices_of_row[next[rows[p]]++] = v;

      std::vector<idx_t> seen(n_vertices, -1);
      for (idx_t v = 0; v < n_vertices; ++v)
        {
          seen[v] = v;
          for (long p = graph.row_start[v]; p < graph.row_start[v + 1]; ++p)
            for (long q = vertex_start[rows[p]]; q < vertex_start[rows[p] + 1];
                 ++q)
              if (const idx_t w = vertices_of_row[q]; seen[w] != v)
                {
                  seen[w] = v;
                  graph.neighbours.push_back(w);
                }
          graph.offsets.push_back(graph.neighbours.size());
        }
    }



    /**
     * A column pre-ordering for UMFPACK's unsymmetric strategy of the
     * matrix in compressed columns @p start, @p index (n x n): METIS's
     * nested dissection of the graph of its columns, two adjacent where
     * they share a row (the pattern of M^T M, which UMFPACK's own METIS
     * option orders too), on ColumnGraph: singletons (a removed unknown's
     * row x_i = 0, an open pair) first and left out of the graph, where
     * they would join every pair around them, and a pair's directions one
     * vertex. On cube_5x5x5's Newton system (n = 7245) that took 0.02 s
     * against 1.0 s for UMFPACK's METIS option, for about the same fill
     * (3.53 against 3.39 million entries of L and U; COLAMD's 5.87
     * million). Empty where METIS fails: then UMFPACK orders.
     */
    std::vector<long>
    nested_dissection(const long               n,
                      const std::vector<long> &start,
                      const std::vector<long> &index,
                      const unsigned int       block_size,
                      const unsigned int       n_blocked)
    {
      ColumnGraph graph;
      mark_singletons(n, start, index, graph);
      merge_blocks(
        n, start, index, block_size, std::min<long>(n_blocked, n), graph);
      connect(n, graph);
      // METIS's indices are idx_t (32 bits here).
      if (graph.neighbours.size() >
          static_cast<std::size_t>(std::numeric_limits<idx_t>::max()))
        return {};

      idx_t              n_vertices = graph.weights.size();
      std::vector<idx_t> permutation(n_vertices), inverse(n_vertices);
      std::iota(permutation.begin(), permutation.end(), 0);
      // A graph without edges METIS is not given (CHOLMOD does not either).
      if (n_vertices > 2 && !graph.neighbours.empty())
        {
          std::array<idx_t, METIS_NOPTIONS> options;
          METIS_SetDefaultOptions(options.data());
          if (METIS_NodeND(&n_vertices,
                           graph.offsets.data(),
                           graph.neighbours.data(),
                           graph.weights.data(),
                           options.data(),
                           permutation.data(),
                           inverse.data()) != METIS_OK)
            return {};
        }

      std::vector<long> order;
      order.reserve(n);
      for (long j = 0; j < n; ++j)
        if (graph.column_out[j])
          order.push_back(j);
      for (const idx_t v : permutation) // the vertex at each position
        for (long j = graph.first_column[v], k = 0; k < graph.weights[v]; ++j)
          if (!graph.column_out[j])
            {
              order.push_back(j);
              ++k;
            }
      return order;
    }



    void
    check(const long status, const char *step)
    {
      AssertThrow(status == UMFPACK_OK,
                  ExcMessage(std::string("UMFPACK's ") + step +
                             " failed with status " + std::to_string(status) +
                             " (umfpack.h lists the codes)."));
    }
  } // namespace



  SparseLU::SparseLU(const Ordering ordering)
    : ordering(ordering)
  {}



  SparseLU::~SparseLU()
  {
    clear_numeric();
    clear_symbolic();
  }



  void
  SparseLU::clear_symbolic()
  {
    if (symbolic != nullptr)
      umfpack_dl_free_symbolic(&symbolic);
    symbolic = nullptr;
  }



  void
  SparseLU::clear_numeric()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    numeric = nullptr;
  }



  bool
  SparseLU::factorize(const SparseMatrix<double> &matrix, const bool drop_zeros)
  {
    Assert(matrix.m() == matrix.n(), ExcNotQuadratic());
    const long n = matrix.m();
    // A's rows as A^T's columns, sorted (deal.II keeps the diagonal first).
    std::vector<long>   start(n + 1, 0), index;
    std::vector<double> value;
    index.reserve(matrix.n_nonzero_elements());
    value.reserve(matrix.n_nonzero_elements());
    std::vector<std::pair<long, double>> row;
    for (long i = 0; i < n; ++i)
      {
        row.clear();
        for (auto entry = matrix.begin(i); entry != matrix.end(i); ++entry)
          if (!drop_zeros || entry->value() != 0.)
            row.emplace_back(entry->column(), entry->value());
        std::sort(row.begin(), row.end());
        for (const auto &[column, v] : row)
          {
            index.push_back(column);
            value.push_back(v);
          }
        start[i + 1] = index.size();
      }
    const bool same_pattern =
      symbolic != nullptr && start == column_start && index == row_index;
    column_start.swap(start);
    row_index.swap(index);
    values.swap(value);

    const auto                       c = control(ordering);
    std::array<double, UMFPACK_INFO> info;
    clear_numeric();
    if (same_pattern)
      ++reused;
    else
      {
        clear_symbolic();
        // METIS (here or through UMFPACK) puts its own handler on SIGTERM
        // while it runs and turns a signal into an error return: a SIGTERM
        // in those milliseconds is lost (the run goes on with COLAMD's
        // order; send it again). Holding signals back in this thread is no
        // cure: OpenBLAS's threads do not block them, and one of them would
        // then run METIS's handler, which jumps into this thread's stack.
        std::vector<long> order;
        if (ordering == Ordering::nested_dissection)
          order = nested_dissection(
            n, column_start, row_index, block_size, n_blocked);
        // With an order given, UMFPACK's unsymmetric strategy keeps it
        // (up to a postordering); without, it orders by c.
        check(umfpack_dl_qsymbolic(n,
                                   n,
                                   column_start.data(),
                                   row_index.data(),
                                   values.data(),
                                   order.empty() ? nullptr : order.data(),
                                   &symbolic,
                                   c.data(),
                                   info.data()),
              "symbolic analysis");
        given_order = info[UMFPACK_ORDERING_USED] == UMFPACK_ORDERING_GIVEN;
        ++analysed;
      }
    const long status = umfpack_dl_numeric(column_start.data(),
                                           row_index.data(),
                                           values.data(),
                                           symbolic,
                                           &numeric,
                                           c.data(),
                                           info.data());
    if (status == UMFPACK_WARNING_singular_matrix)
      {
        clear_numeric();
        return false;
      }
    check(status, "numeric factorisation");
    factor_flops   = info[UMFPACK_FLOPS];
    factor_entries = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
    return true;
  }



  void
  SparseLU::set_blocks(const unsigned int size, const unsigned int n_in_blocks)
  {
    Assert(size > 0, ExcMessage("SparseLU: a block has at least one row."));
    if (size != block_size || n_in_blocks != n_blocked)
      clear_symbolic();
    block_size = size;
    n_blocked  = n_in_blocks;
  }



  void
  SparseLU::set_ordering(const Ordering new_ordering)
  {
    if (new_ordering != ordering)
      clear_symbolic();
    ordering = new_ordering;
  }



  void
  SparseLU::solve(Vector<double> &x, const bool refine) const
  {
    Assert(numeric != nullptr, ExcMessage("SparseLU: nothing factorised."));
    Assert(x.size() + 1 == column_start.size(),
           ExcDimensionMismatch(x.size(), column_start.size() - 1));
    const Vector<double> b = x;
    auto                 c = control(ordering);
    if (!refine)
      c[UMFPACK_IRSTEP] = 0;
    std::array<double, UMFPACK_INFO> info;
    // The factors are of A^T: UMFPACK_Aat solves (A^T)^T x = A x = b.
    check(umfpack_dl_solve(UMFPACK_Aat,
                           column_start.data(),
                           row_index.data(),
                           values.data(),
                           x.begin(),
                           b.begin(),
                           numeric,
                           c.data(),
                           info.data()),
          "solve");
  }



  double
  SparseLU::substitutions_per_factorization() const
  {
    return factor_entries > 0. ? factor_flops / (2. * factor_entries) : 0.;
  }



  bool
  SparseLU::order_given() const
  {
    return given_order;
  }



  std::pair<unsigned int, unsigned int>
  SparseLU::symbolic_counts() const
  {
    return {reused, analysed};
  }
} // namespace mbfem
