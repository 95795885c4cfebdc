// The file rows of each process's snapshot part (core/snapshot_part.hpp): against the
// one-process order built by hand, every particle tagged with its rank and layer.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "core/snapshot_part.hpp"

using namespace granshock;

// Slabs along y: one layer, so each rank's rows follow the lower ranks' in one run.
TEST(FileRowsByLayer, OneLayerIsOneRunPerRankInRankOrder) {
  const std::vector<long> counts{5, 0, 7};  // 3 ranks x 1 layer; rank 1 empty
  EXPECT_EQ(file_rows_by_layer(counts, 1, 0), (std::vector<FileRows>{{0, 5}}));
  EXPECT_TRUE(file_rows_by_layer(counts, 1, 1).empty());
  EXPECT_EQ(file_rows_by_layer(counts, 1, 2), (std::vector<FileRows>{{5, 7}}));
}

// Slabs along x: a layer per grid row, ranks in x order within each. The one-process
// order, listed layer by layer and rank by rank, gives every rank's rows.
TEST(FileRowsByLayer, LayersInterleaveTheRanksAsOneProcessOrdersThem) {
  const int ranks = 3, layers = 4;
  const std::vector<long> counts{2, 0, 3, 1,   // rank 0, layers 0..3
                                 4, 1, 0, 0,   // rank 1
                                 0, 2, 5, 1};  // rank 2
  std::vector<int> owner;                      // of each file row, in one process's order
  for (int layer = 0; layer < layers; ++layer)
    for (int r = 0; r < ranks; ++r)
      owner.insert(owner.end(), std::size_t(counts[std::size_t(r * layers + layer)]), r);
  std::vector<int> filled(owner.size(), 0);
  for (int r = 0; r < ranks; ++r) {
    long previous_end = -1;
    for (const FileRows& rows : file_rows_by_layer(counts, layers, r)) {
      EXPECT_GT(rows.first, previous_end) << "runs increase and do not touch (merged)";
      previous_end = rows.first + rows.count;
      for (long k = rows.first; k < rows.first + rows.count; ++k) {
        EXPECT_EQ(owner.at(std::size_t(k)), r) << "row " << k;
        ++filled[std::size_t(k)];
      }
    }
  }
  EXPECT_EQ(filled, std::vector<int>(owner.size(), 1)) << "each row once";
  // Layer by layer (rank 0, 1, 2): rows 0-5 | 6-8 | 9-16 | 17-18.
  EXPECT_EQ(file_rows_by_layer(counts, layers, 0),
            (std::vector<FileRows>{{0, 2}, {9, 3}, {17, 1}}));
  // Rank 1's rows of layers 0 and 1 touch (rank 2 has none in layer 0): one run.
  EXPECT_EQ(file_rows_by_layer(counts, layers, 1), (std::vector<FileRows>{{2, 5}}));
  EXPECT_EQ(file_rows_by_layer(counts, layers, 2),
            (std::vector<FileRows>{{7, 2}, {12, 5}, {18, 1}}));
}

TEST(FileRowsByLayer, RunsThatTouchAreMerged) {
  // Rank 1 is alone in layers 1 and 2: its two layers are one run.
  const std::vector<long> counts{3, 0, 0, 2,  //
                                 1, 4, 6, 0};
  EXPECT_EQ(file_rows_by_layer(counts, 4, 1), (std::vector<FileRows>{{3, 11}}));
  EXPECT_EQ(file_rows_by_layer(counts, 4, 0), (std::vector<FileRows>{{0, 3}, {14, 2}}));
}

TEST(FileRowsByLayer, CountsThatAreNotRanksByLayersAreRefused) {
  EXPECT_THROW(file_rows_by_layer({1, 2, 3}, 2, 0), std::invalid_argument);
  EXPECT_THROW(file_rows_by_layer({1, 2}, 1, 2), std::invalid_argument);
}

// The source of each row, from every rank's runs concatenated in rank order: rank 0's two
// particles fill rows 2-3, rank 1's rows 0-1.
TEST(RowSources, EachRowFromItsRanksPart) {
  EXPECT_EQ(row_sources({{2, 2}, {0, 2}}, 4, 4), (std::vector<int>{2, 3, 0, 1}));
}

TEST(RowSources, RowsFilledTwiceOrNotAtAllAreADefect) {
  EXPECT_THROW(row_sources({{0, 2}, {1, 2}}, 3, 4), std::logic_error);  // row 1 twice
  EXPECT_THROW(row_sources({{0, 2}}, 3, 2), std::logic_error);          // row 2 empty
  EXPECT_THROW(row_sources({{0, 3}}, 3, 2), std::logic_error);          // more rows than parts
}
