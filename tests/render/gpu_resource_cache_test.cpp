// The GPU caches' policy alone (no GL): least recently used by frame first, bytes accounted,
// nothing the current frame used is evicted, budget 0 keeps just the frame's set.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "render/gl/gpu_resource_cache.hpp"

namespace trailray::render {
namespace {

// A value whose destruction is observable, as a GL object's deletion would be.
using Value = std::shared_ptr<int>;
using Cache = GpuResourceCache<std::string, Value>;

Value value(int n) { return std::make_shared<int>(n); }

TEST(GpuResourceCache, EvictsTheLeastRecentlyUsedFirst) {
  Cache cache(30);
  cache.begin_frame();
  cache.insert("a", value(1), 10);
  cache.insert("b", value(2), 10);
  cache.insert("c", value(3), 10);
  cache.evict_to_budget();
  EXPECT_EQ(cache.size(), 3u);

  cache.begin_frame();
  ASSERT_NE(cache.find("a"), nullptr);  // a is now more recent than b and c
  cache.insert("d", value(4), 10);
  cache.evict_to_budget();
  EXPECT_FALSE(cache.contains("b"));
  EXPECT_TRUE(cache.contains("a"));
  EXPECT_TRUE(cache.contains("c"));
  EXPECT_TRUE(cache.contains("d"));
  EXPECT_EQ(cache.used_bytes(), 30u);

  cache.begin_frame();
  cache.insert("e", value(5), 20);
  cache.evict_to_budget();  // c, then a (the older of the rest) go
  EXPECT_FALSE(cache.contains("c"));
  EXPECT_FALSE(cache.contains("a"));
  EXPECT_TRUE(cache.contains("d"));
  EXPECT_TRUE(cache.contains("e"));
  EXPECT_EQ(cache.used_bytes(), 30u);
  EXPECT_EQ(cache.stats().evictions, 2u);
}

TEST(GpuResourceCache, EvictingDestroysTheValue) {
  Cache cache(0);
  cache.begin_frame();
  const std::weak_ptr<int> watched = cache.insert("a", value(1), 10);
  cache.evict_to_budget();
  EXPECT_FALSE(watched.expired());  // used by this frame
  cache.begin_frame();
  cache.evict_to_budget();
  EXPECT_TRUE(watched.expired());
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.used_bytes(), 0u);
}

TEST(GpuResourceCache, CountsBytesThroughReplaceAndErase) {
  Cache cache(1000);
  cache.begin_frame();
  cache.insert("a", value(1), 100);
  cache.insert("b", value(2), 50);
  EXPECT_EQ(cache.used_bytes(), 150u);
  cache.insert("a", value(3), 30);  // replaced: its old bytes are gone
  EXPECT_EQ(cache.used_bytes(), 80u);
  EXPECT_EQ(**cache.find("a"), 3);
  cache.erase("b");
  cache.erase("nothing");
  EXPECT_EQ(cache.used_bytes(), 30u);
  EXPECT_EQ(cache.size(), 1u);

  const GpuCacheStats s = cache.stats();
  EXPECT_EQ(s.entries, 1u);
  EXPECT_EQ(s.bytes, 30u);
  EXPECT_EQ(s.budget_bytes, 1000u);
  EXPECT_EQ(s.frame_entries, 1u);
  EXPECT_EQ(s.frame_bytes, 30u);
  EXPECT_EQ(s.uploads, 3u);
  EXPECT_EQ(s.uploaded_bytes, 180u);
  cache.clear();
  EXPECT_EQ(cache.used_bytes(), 0u);
  EXPECT_EQ(cache.stats().frame_bytes, 0u);
}

TEST(GpuResourceCache, TheFrameCountsEachEntryOnceAndRestartsItsCounters) {
  Cache cache(1000);
  cache.begin_frame();
  cache.insert("a", value(1), 10);
  cache.insert("b", value(2), 20);
  cache.find("a");
  cache.find("a");
  EXPECT_EQ(cache.stats().frame_entries, 2u);
  EXPECT_EQ(cache.stats().frame_bytes, 30u);

  cache.begin_frame();
  EXPECT_EQ(cache.stats().frame_entries, 0u);
  EXPECT_EQ(cache.stats().uploads, 0u);
  EXPECT_EQ(cache.find("missing"), nullptr);
  cache.find("b");
  cache.find("b");
  EXPECT_TRUE(cache.used_this_frame("b"));
  EXPECT_FALSE(cache.used_this_frame("a"));
  EXPECT_EQ(cache.stats().frame_entries, 1u);
  EXPECT_EQ(cache.stats().frame_bytes, 20u);
  EXPECT_EQ(cache.stats().uploads, 0u);
}

TEST(GpuResourceCache, NeverEvictsWhatTheFrameUsesEvenOverBudget) {
  Cache cache(30);
  cache.begin_frame();
  Value* first = &cache.insert("a", value(1), 10);
  for (const char* key : {"b", "c", "d", "e"}) cache.insert(key, value(2), 10);
  EXPECT_EQ(cache.find("a"), first);  // other inserts do not move it
  cache.evict_to_budget();
  EXPECT_EQ(cache.size(), 5u);  // 50 bytes: the frame needs them all
  EXPECT_EQ(cache.used_bytes(), 50u);
  EXPECT_EQ(cache.stats().evictions, 0u);

  // The next frame uses two of them: the least recent of the others go until the budget holds.
  cache.begin_frame();
  cache.find("a");
  cache.find("c");
  cache.evict_to_budget();
  EXPECT_TRUE(cache.contains("a"));
  EXPECT_TRUE(cache.contains("c"));
  EXPECT_TRUE(cache.contains("e"));  // the most recent of b, d, e
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_EQ(cache.used_bytes(), 30u);
  EXPECT_EQ(cache.stats().evictions, 2u);
}

TEST(GpuResourceCache, BudgetZeroKeepsOnlyTheFramesOwn) {
  Cache cache(0);
  cache.begin_frame();
  cache.insert("a", value(1), 10);
  cache.insert("b", value(2), 10);
  cache.evict_to_budget();
  EXPECT_EQ(cache.size(), 2u);

  cache.begin_frame();
  cache.find("b");
  cache.insert("c", value(3), 10);
  cache.evict_to_budget();
  EXPECT_FALSE(cache.contains("a"));
  EXPECT_TRUE(cache.contains("b"));
  EXPECT_TRUE(cache.contains("c"));
  EXPECT_EQ(cache.used_bytes(), 20u);

  cache.begin_frame();  // a frame that draws nothing
  cache.evict_to_budget();
  EXPECT_EQ(cache.size(), 0u);
  EXPECT_EQ(cache.used_bytes(), 0u);
}

TEST(GpuResourceCache, ALargerBudgetKeepsMoreAndASmallerOneEvictsAtTheNextFrameEnd) {
  Cache cache(100);
  for (int frame = 0; frame < 10; ++frame) {
    cache.begin_frame();
    cache.insert(std::to_string(frame), value(frame), 10);
    cache.evict_to_budget();
  }
  EXPECT_EQ(cache.size(), 10u);
  cache.set_budget(35);
  cache.begin_frame();
  cache.find("0");  // the oldest, now the most recent
  cache.evict_to_budget();
  EXPECT_EQ(cache.size(), 3u);
  EXPECT_TRUE(cache.contains("0"));
  EXPECT_TRUE(cache.contains("9"));
  EXPECT_TRUE(cache.contains("8"));
  EXPECT_EQ(cache.stats().budget_bytes, 35u);
}

}  // namespace
}  // namespace trailray::render
