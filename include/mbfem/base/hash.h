#ifndef mbfem_base_hash_h
#define mbfem_base_hash_h

#include <cstdint>

namespace mbfem
{
  /**
   * FNV-1a's offset and prime, one 64-bit word at a time: the hashes that
   * compare data cheaply (the ranks' states under mpirun, the rows of
   * Newton's Jacobian since its factorisation). Not for security: a
   * collision only costs the check it serves.
   */
  namespace Hash
  {
    constexpr std::uint64_t start = 14695981039346656037ull;

    /** @p hash with @p word mixed in. */
    constexpr std::uint64_t
    add(const std::uint64_t hash, const std::uint64_t word)
    {
      return (hash ^ word) * 1099511628211ull;
    }
  } // namespace Hash
} // namespace mbfem

#endif
