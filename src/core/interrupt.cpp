#include "core/interrupt.h"

#include <atomic>

namespace froth {
namespace {
std::atomic<bool> g_interrupt{false};
static_assert(std::atomic<bool>::is_always_lock_free, "needed for signal safety");
} // namespace

void request_interrupt() noexcept { g_interrupt.store(true); }
bool consume_interrupt() noexcept { return g_interrupt.exchange(false); }
bool interrupt_pending() noexcept { return g_interrupt.load(); }

} // namespace froth
