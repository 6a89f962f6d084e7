#include "mocap/layout/subset_error.h"

#include "mocap/math/bounded_least_squares.h"
#include "mocap/base/error.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <string>

namespace mocap {

namespace {

Eigen::MatrixXd gatherRows(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                           const std::vector<Eigen::Index>& rows, const char* what)
{
  if (rows.empty())
    throw InvalidArgument(std::string("subset errors: there are no ") + what + " frames");
  Eigen::MatrixXd result(static_cast<Eigen::Index>(rows.size()), frames.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i] < 0 || rows[i] >= frames.rows())
      throw InvalidArgument(std::string("subset errors: ") + what + " row " + std::to_string(rows[i]) +
                            " out of range");
    result.row(static_cast<Eigen::Index>(i)) = frames.row(rows[i]);
  }
  if (!result.allFinite())
    throw InvalidArgument(std::string("subset errors: a ") + what + " frame is not finite");
  return result;
}

// Memory for the blocks one subset's evaluation gathers, kept per thread: a layout search scores
// thousands of subsets, and a fresh matrix per block made allocation the larger cost (the greater
// by far under AddressSanitizer, whose quarantine turns each allocation into fresh pages).
class BlockScratch
{
public:
  /// Slot `slot` as a rows × cols matrix; slots never overlap. Contents are left as they were.
  Eigen::Map<Eigen::MatrixXd> block(std::size_t slot, Eigen::Index rows, Eigen::Index cols)
  {
    const auto size = static_cast<std::size_t>(rows * cols);
    if (m_slots.size() <= slot)
      m_slots.resize(slot + 1);
    if (m_slots[slot].size() < size)
      m_slots[slot].resize(size);
    return {m_slots[slot].data(), rows, cols};
  }

private:
  std::vector<std::vector<double>> m_slots;
};

BlockScratch& threadScratch()
{
  thread_local BlockScratch scratch;
  return scratch;
}

// out = g(rows, cols), without IndexedView's temporary.
void gather(const Eigen::MatrixXd& g, const std::vector<Eigen::Index>& rows, const std::vector<Eigen::Index>& cols,
            Eigen::Map<Eigen::MatrixXd>& out)
{
  for (std::size_t j = 0; j < cols.size(); ++j)
    for (std::size_t i = 0; i < rows.size(); ++i)
      out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = g(rows[i], cols[j]);
}

} // namespace

SubsetErrors::SubsetErrors(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                           const std::vector<Eigen::Index>& training, const std::vector<Eigen::Index>& test,
                           BlendshapeBasis basis, const SubsetErrorOptions& options)
    : m_basis(std::move(basis))
{
  if (!(options.ridge >= 0.0) || !std::isfinite(options.ridge) || !(options.blendshapeWeight >= 0.0) ||
      !std::isfinite(options.blendshapeWeight) || options.objectiveFrames < 1)
    throw InvalidArgument(
        "subset errors: the ridge and blendshape weight must be finite and ≥ 0, objectiveFrames ≥ 1");
  if (frames.cols() < 3 || frames.cols() % 3 != 0)
    throw InvalidArgument("subset errors: frames must hold 3 values per marker");
  if (m_basis.deltas.rows() != frames.cols() || m_basis.neutral.size() != frames.cols())
    throw InvalidArgument("subset errors: the blendshape basis does not match the frames");
  const Eigen::MatrixXd trainingRows = gatherRows(frames, training, "training");
  m_testFrames = gatherRows(frames, test, "test");
  m_testCount = m_testFrames.rows();
  const Eigen::RowVectorXd mean = trainingRows.colwise().mean();
  const Eigen::MatrixXd centred = trainingRows.rowwise() - mean;
  m_trainingGram = centred.transpose() * centred;
  const Eigen::MatrixXd testCentred = m_testFrames.rowwise() - mean;
  m_testGram = testCentred.transpose() * testCentred;
  m_fullWeights = solveBlendshapeWeights(m_basis, m_testFrames);
  // A floor keeps exactly dependent subset coordinates (copies of a marker) solvable at ridge 0.
  const double meanVariance = m_trainingGram.trace() / static_cast<double>(m_trainingGram.rows());
  m_ridge = std::max(options.ridge, 1e-12) * std::max(meanVariance, 1e-300);
  m_blendshapeWeight = options.blendshapeWeight;

  const auto count = static_cast<Eigen::Index>(training.size());
  const Eigen::Index used = std::min(count, options.objectiveFrames);
  m_objectiveFrames.resize(used, frames.cols());
  for (Eigen::Index i = 0; i < used; ++i)
    m_objectiveFrames.row(i) = trainingRows.row(i * count / used);
  m_objectiveWeights = solveBlendshapeWeights(m_basis, m_objectiveFrames);
  m_testOffsets = (m_testFrames.rowwise() - m_basis.neutral).transpose();
  m_objectiveOffsets = (m_objectiveFrames.rowwise() - m_basis.neutral).transpose();

  // The selection objective scores the model on training frames it was not fitted on: 20
  // consecutive chunks of the training rows, every fourth held apart, so a selection is not
  // rewarded for fitting noise.
  std::vector<Eigen::Index> fit, validation;
  for (Eigen::Index i = 0; i < count; ++i)
    ((i * 20 / count) % 4 == 3 ? validation : fit).push_back(i);
  if (fit.size() < 2 || validation.empty()) {
    fit.clear();
    validation.clear();
    for (Eigen::Index i = 0; i < count; ++i)
      fit.push_back(i), validation.push_back(i);
  }
  const Eigen::MatrixXd fitRows = trainingRows(fit, Eigen::all);
  const Eigen::RowVectorXd fitMean = fitRows.colwise().mean();
  const Eigen::MatrixXd fitCentred = fitRows.rowwise() - fitMean;
  m_fitGram = fitCentred.transpose() * fitCentred;
  const Eigen::MatrixXd validationCentred = trainingRows(validation, Eigen::all).rowwise() - fitMean;
  m_validationGram = validationCentred.transpose() * validationCentred;
  m_emptyResidual = m_validationGram.trace();
  m_emptyWeightError = m_objectiveWeights.squaredNorm() / static_cast<double>(m_objectiveWeights.size());
}

double SubsetErrors::motionRms() const
{
  return std::sqrt(m_testGram.trace() / static_cast<double>(m_testCount * markerCount()));
}

std::vector<Eigen::Index> SubsetErrors::coordinates(const std::vector<Eigen::Index>& markers) const
{
  std::vector<Eigen::Index> result;
  result.reserve(3 * markers.size());
  for (const Eigen::Index m : markers) {
    if (m < 0 || m >= markerCount())
      throw InvalidArgument("subset errors: marker " + std::to_string(m) + " out of range");
    for (Eigen::Index axis = 0; axis < 3; ++axis)
      result.push_back(3 * m + axis);
  }
  return result;
}

// The coordinates not in `c`: the ones a subset has to predict (its own are measured).
std::vector<Eigen::Index> SubsetErrors::complement(const std::vector<Eigen::Index>& c) const
{
  std::vector<bool> inSubset(static_cast<std::size_t>(m_trainingGram.rows()), false);
  for (const Eigen::Index i : c)
    inSubset[static_cast<std::size_t>(i)] = true;
  std::vector<Eigen::Index> rest;
  for (Eigen::Index i = 0; i < m_trainingGram.rows(); ++i)
    if (!inSubset[static_cast<std::size_t>(i)])
      rest.push_back(i);
  return rest;
}

// ‖T_U − T_S·B‖² from the Gram matrix E of the evaluated frames, with B = (F_SS + λI)⁻¹ F_SU the
// ridge-regression map, fitted on the Gram matrix F, from the centred subset coordinates S to the
// others U: tr(E_UU) − 2·Σ B∘E_SU + Σ B∘(E_SS·B). Works in the thread's scratch memory.
double SubsetErrors::heldOutError(const Eigen::MatrixXd& fitGram, const Eigen::MatrixXd& evaluatedGram,
                                  const std::vector<Eigen::Index>& c) const
{
  if (c.empty())
    return evaluatedGram.trace();
  const std::vector<Eigen::Index> rest = complement(c);
  if (rest.empty())
    return 0.0;
  const auto s = static_cast<Eigen::Index>(c.size()), u = static_cast<Eigen::Index>(rest.size());
  BlockScratch& scratch = threadScratch();
  auto fitSS = scratch.block(0, s, s);
  auto b = scratch.block(1, s, u);
  auto evaluatedSS = scratch.block(2, s, s);
  auto evaluatedSU = scratch.block(3, s, u);
  auto inner = scratch.block(4, s, u);
  gather(fitGram, c, c, fitSS);
  fitSS.diagonal().array() += m_ridge;
  gather(fitGram, c, rest, b);
  const Eigen::LDLT<Eigen::Ref<Eigen::MatrixXd>> factor(fitSS);  // factorises in place
  factor.solveInPlace(b);
  gather(evaluatedGram, c, c, evaluatedSS);
  gather(evaluatedGram, c, rest, evaluatedSU);
  inner.noalias() = evaluatedSS * b;
  double restTrace = 0.0;
  for (const Eigen::Index i : rest)
    restTrace += evaluatedGram(i, i);
  const double sse =
      restTrace - 2.0 * (b.array() * evaluatedSU.array()).sum() + (b.array() * inner.array()).sum();
  return std::max(0.0, sse);
}

double SubsetErrors::trainingResidual(const std::vector<Eigen::Index>& markers) const
{
  return heldOutError(m_trainingGram, m_trainingGram, coordinates(markers));
}

double SubsetErrors::reconstructionRmse(const std::vector<Eigen::Index>& markers) const
{
  const double sse = heldOutError(m_trainingGram, m_testGram, coordinates(markers));
  return std::sqrt(sse / static_cast<double>(m_testCount * markerCount()));
}

double SubsetErrors::weightError(const std::vector<Eigen::Index>& c, const Eigen::MatrixXd& offsets,
                                 const Eigen::MatrixXd& fullWeights) const
{
  if (c.empty())
    return fullWeights.squaredNorm() / static_cast<double>(fullWeights.size());
  const Eigen::Index k = m_basis.keyPoseCount();
  const Eigen::MatrixXd a = m_basis.deltas(c, Eigen::all);
  const BoundedLeastSquares solver(a, Eigen::VectorXd::Zero(k), Eigen::VectorXd::Ones(k));
  // Aᵀ(x_S − n_S) for every frame at once.
  BlockScratch& scratch = threadScratch();
  auto subsetOffsets = scratch.block(5, static_cast<Eigen::Index>(c.size()), offsets.cols());
  for (Eigen::Index f = 0; f < offsets.cols(); ++f)
    for (std::size_t i = 0; i < c.size(); ++i)
      subsetOffsets(static_cast<Eigen::Index>(i), f) = offsets(c[i], f);
  auto rhs = scratch.block(6, k, offsets.cols());
  rhs.noalias() = a.transpose() * subsetOffsets;
  double sum = 0.0;
  Eigen::VectorXd previous;
  BoundedLeastSquares::Workspace workspace;
  for (Eigen::Index f = 0; f < offsets.cols(); ++f) {
    solver.solveNormal(rhs.col(f), previous, f > 0, workspace);
    sum += (previous.transpose() - fullWeights.row(f)).squaredNorm();
  }
  return sum / static_cast<double>(fullWeights.size());
}

double SubsetErrors::blendshapeError(const std::vector<Eigen::Index>& markers) const
{
  return weightError(coordinates(markers), m_testOffsets, m_fullWeights);
}

double SubsetErrors::trainingObjective(const std::vector<Eigen::Index>& markers) const
{
  const std::vector<Eigen::Index> c = coordinates(markers);
  const double residual = heldOutError(m_fitGram, m_validationGram, c) / std::max(m_emptyResidual, 1e-300);
  const double weights =
      weightError(c, m_objectiveOffsets, m_objectiveWeights) / std::max(m_emptyWeightError, 1e-300);
  return residual + m_blendshapeWeight * weights;
}

} // namespace mocap
