#pragma once

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace mocap {

/// Column given to a row that stays unassigned.
constexpr Eigen::Index kUnassigned = -1;

/// Optimal assignment of rows to columns on a dense cost matrix (#rows × #cols, entries finite
/// and ≥ 0) with a gate: minimises Σ cost(r, c(r)) over assigned rows + gate · #unassigned rows,
/// each column used at most once and no pair with cost > gate used. An infinite gate means "assign
/// as many rows as possible, then at least cost" (a gate above every alternative).
/// The gated graph (pairs with cost ≤ gate) is split into connected components first; a component
/// of one row and one column is assigned directly, larger ones by the shortest-augmenting-path
/// Hungarian method (Kuhn 1955; Jonker & Volgenant 1987 potentials) on the component padded with
/// one private "unassigned" column per row. Tracking step of §2 of the paper (frame-to-frame
/// correspondence). Returns the column of each row or kUnassigned.
/// O(Σ components r²·(c + r)), at most O(#rows² · (#cols + #rows)); O(#rows · #cols) when
/// the gate separates every pair. Throws InvalidArgument for a negative or non-finite cost or a
/// NaN or negative gate.
[[nodiscard]] std::vector<Eigen::Index> assignMinimumCost(const Eigen::Ref<const Eigen::MatrixXd>& cost,
                                                          double gate = std::numeric_limits<double>::infinity());

/// Σ cost(r, c(r)) over the assigned rows of `assignment` (as returned above). O(#rows).
[[nodiscard]] double assignmentCost(const Eigen::Ref<const Eigen::MatrixXd>& cost,
                                    const std::vector<Eigen::Index>& assignment);

} // namespace mocap
