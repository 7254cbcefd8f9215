// The split of an image's passes among ranks, and the one line rank 0 prints for failed ranks.
#include <gtest/gtest.h>

#include <vector>

#include "distributed/agree.h"
#include "distributed/work_split.h"

namespace penumbra::distributed {
namespace {

// Every pass of every round lands on exactly one rank, in contiguous pieces whose sizes differ
// by at most one: the union is the single-process render's passes, with no pass twice.
TEST(WorkSplit, SharesCoverEveryPassOnce) {
    for (std::uint32_t total : {0u, 1u, 5u, 64u, 100u, 4097u})
        for (std::uint32_t perRound : {1u, 16u, 64u})
            for (int ranks : {1, 2, 3, 7, 70}) {
                std::vector<int> owner(total, -1);
                for (std::uint32_t round = 0;; ++round) {
                    const PassRange all = roundRange(round, perRound, total);
                    if (all.count == 0) break;
                    EXPECT_EQ(all.first, round * perRound);
                    std::uint32_t smallest = UINT32_MAX, largest = 0, next = all.first;
                    for (int r = 0; r < ranks; ++r) {
                        const PassRange mine = shareOf(all, r, ranks);
                        EXPECT_EQ(mine.first, next) << "pieces are contiguous and in rank order";
                        next = mine.end();
                        smallest = std::min(smallest, mine.count);
                        largest = std::max(largest, mine.count);
                        for (std::uint32_t p = mine.first; p < mine.end(); ++p) {
                            ASSERT_LT(p, total);
                            EXPECT_EQ(owner[p], -1) << "pass " << p << " twice";
                            owner[p] = r;
                        }
                    }
                    EXPECT_EQ(next, all.end());
                    EXPECT_LE(largest - smallest, 1u);
                }
                for (std::uint32_t p = 0; p < total; ++p) EXPECT_NE(owner[p], -1) << "pass " << p << " never rendered";
            }
}

TEST(WorkSplit, RoundRangeStopsAtTheEnd) {
    EXPECT_EQ(roundRange(0, 64, 100).count, 64u);
    EXPECT_EQ(roundRange(1, 64, 100).first, 64u);
    EXPECT_EQ(roundRange(1, 64, 100).count, 36u);
    EXPECT_EQ(roundRange(2, 64, 100).count, 0u);
}

TEST(Verdict, SameFailureEverywhereIsTheMessageAlone) {
    EXPECT_EQ(verdictLine({1, 1, 1}, {"no such file", "no such file", "no such file"}, {"a", "a", "b"}), "no such file");
}

TEST(Verdict, OneRankNamesRankAndHost) {
    EXPECT_EQ(verdictLine({0, 0, 2}, {"", "", "no GPU here"}, {"a", "a", "node7"}), "rank 2 on node7: no GPU here");
}

TEST(Verdict, SeveralRanksNameTheFirstAndCount) {
    EXPECT_EQ(verdictLine({0, 1, 1}, {"", "x", "y"}, {"a", "b", "c"}), "rank 1 on b: x (2 of 3 ranks failed)");
    // Every rank failed, but not the same way: still say which.
    EXPECT_EQ(verdictLine({1, 1}, {"x", "y"}, {"a", "b"}), "rank 0 on a: x (2 of 2 ranks failed)");
}

TEST(Verdict, NoFailureNoLine) { EXPECT_EQ(verdictLine({0, 0}, {"", ""}, {"a", "b"}), ""); }

}  // namespace
}  // namespace penumbra::distributed
