// Moving values onto the cycle and back, and the rule for vertices the cycle misses: they take
// the one-ring mean of their neighbours' values (quantities) or of their neighbours' change
// (the filtered signal), computed here from the faces, not by the library's own loop.
#include "cycle/cycle_decomposition.h"
#include "cycle/cycle_signal.h"
#include "mesh/mean_curvature.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <set>

namespace hht {
namespace {

std::vector<std::set<int>> one_rings(const test::ArrayMesh& m) {
  std::vector<std::set<int>> ring(m.vertices());
  for (Eigen::Index f = 0; f < m.faces.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      ring[m.faces(f, k)].insert(m.faces(f, (k + 1) % 3));
      ring[m.faces(f, (k + 1) % 3)].insert(m.faces(f, k));
    }
  return ring;
}

// The mesh's real cycle with `off` vertices taken out, as if the cycle had missed them.
HamiltonianCycle cycle_missing(const test::ArrayMesh& m, const std::vector<int>& off) {
  HamiltonianCycle cycle;
  std::string error;
  EXPECT_TRUE(hamiltonian_cycle(m.faces, m.vertices(), {}, cycle, error)) << error;
  std::vector<int> order;
  for (int v : cycle.order)
    if (std::find(off.begin(), off.end(), v) == off.end()) order.push_back(v);
  cycle.order = order;
  cycle.segment_begin = {0, static_cast<int>(order.size())};
  cycle.position.assign(m.vertices(), -1);
  for (size_t i = 0; i < order.size(); ++i) cycle.position[order[i]] = static_cast<int>(i);
  cycle.isolated = static_cast<int>(off.size());
  return cycle;
}

class OffCycle : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    ASSERT_TRUE(mean_curvature(mesh.positions, mesh.faces, curvature, error)) << error;
    // two vertices apart from each other, one next to the first
    off = {17, 400, *one_rings(mesh)[17].begin()};
    cycle = cycle_missing(mesh, off);
    ASSERT_TRUE(decompose_along_cycle(cycle, curvature.signal, {}, decomposition, error)) << error;
    ASSERT_GE(decomposition.imf_count(), 2);
    compute_spectra(decomposition);
  }
  const test::ArrayMesh mesh = test::load_data_mesh("fandisk");
  MeanCurvature curvature;
  std::vector<int> off;
  HamiltonianCycle cycle;
  CycleDecomposition decomposition;
};

TEST_F(OffCycle, SignalAlongTheCycleIsReadInCycleOrder) {
  const auto signals = signals_along_cycle(cycle, curvature.signal);
  ASSERT_EQ(signals.size(), 1u);
  ASSERT_EQ(signals[0].size(), cycle.order.size());
  for (size_t i = 0; i < cycle.order.size(); ++i) ASSERT_EQ(signals[0][i], curvature.signal[cycle.order[i]]);
}

TEST_F(OffCycle, FilteredSignalOffTheCycleChangesByTheOneRingMeanOfTheChange) {
  const FrequencyBand band{0.05, 0.5, false};
  const Eigen::VectorXd filtered = filtered_on_vertices(cycle, decomposition, band, 0.25, mesh.faces, curvature.signal);
  const std::vector<double> along =
      filter_by_frequency(decomposition.emd[0], decomposition.spectra[0], band, 0.25);
  const double scale = curvature.signal.cwiseAbs().maxCoeff();
  for (size_t i = 0; i < cycle.order.size(); ++i) ASSERT_NEAR(filtered[cycle.order[i]], along[i], 1e-12 * scale) << i;
  const auto ring = one_rings(mesh);
  for (int v : off) {
    double change = 0;
    int count = 0;
    for (int u : ring[v])
      if (cycle.position[u] >= 0) {
        change += filtered[u] - curvature.signal[u];
        ++count;
      }
    ASSERT_GT(count, 0);
    EXPECT_NEAR(filtered[v], curvature.signal[v] + change / count, 1e-12 * scale) << v;
    EXPECT_GT(std::abs(change / count), 0.0) << "the test needs neighbours that changed";
  }
}

TEST_F(OffCycle, QuantitiesOffTheCycleAreTheOneRingMean) {
  const auto ring = one_rings(mesh);
  for (CycleQuantity what : {CycleQuantity::Imf, CycleQuantity::Frequency, CycleQuantity::Residue}) {
    const Eigen::VectorXd q = quantity_on_vertices(cycle, decomposition, what, 1, mesh.faces);
    const std::vector<double>& along = what == CycleQuantity::Imf         ? decomposition.emd[0].imfs[1]
                                       : what == CycleQuantity::Frequency ? decomposition.spectra[0][1].frequency
                                                                          : decomposition.emd[0].residue;
    for (size_t i = 0; i < cycle.order.size(); ++i) ASSERT_EQ(q[cycle.order[i]], along[i]) << i;
    for (int v : off) {
      double sum = 0;
      int count = 0;
      for (int u : ring[v])
        if (cycle.position[u] >= 0) {
          sum += q[u];
          ++count;
        }
      EXPECT_NEAR(q[v], sum / count, 1e-12 * (1 + q.cwiseAbs().maxCoeff())) << v;
    }
  }
}

TEST_F(OffCycle, CoarsestImfsOffTheCycleChangeByTheOneRingMeanOfTheChange) {
  const Eigen::VectorXd kept = coarsest_on_vertices(cycle, decomposition, 1, mesh.faces, curvature.signal);
  const std::vector<double> along = keep_coarsest(decomposition.emd[0], 1);
  const double scale = curvature.signal.cwiseAbs().maxCoeff();
  for (size_t i = 0; i < cycle.order.size(); ++i) ASSERT_NEAR(kept[cycle.order[i]], along[i], 1e-12 * scale) << i;
  const auto ring = one_rings(mesh);
  for (int v : off) {
    double change = 0;
    int count = 0;
    for (int u : ring[v])
      if (cycle.position[u] >= 0) {
        change += kept[u] - curvature.signal[u];
        ++count;
      }
    EXPECT_NEAR(kept[v], curvature.signal[v] + change / count, 1e-12 * scale) << v;
  }
}

}  // namespace
}  // namespace hht
