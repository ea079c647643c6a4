#include "core/interrupt.h"

#include <atomic>

namespace froth {
namespace {
std::atomic<int> g_requests{0};
std::atomic<int> g_loops{0};
static_assert(std::atomic<int>::is_always_lock_free, "needed for signal safety");
} // namespace

void request_interrupt() noexcept { g_requests.fetch_add(1); }
bool consume_interrupt() noexcept { return g_requests.exchange(0) > 0; }
int interrupt_requests() noexcept { return g_requests.load(); }

EngineLoopScope::EngineLoopScope() noexcept { g_loops.fetch_add(1); }
EngineLoopScope::~EngineLoopScope() { g_loops.fetch_sub(1); }
bool engine_loop_active() noexcept { return g_loops.load() > 0; }

} // namespace froth
