#pragma once
/// A process-wide "please stop" flag. The app's SIGINT handler raises it; long engine loops
/// (evolutions) poll it between steps, so Ctrl-C never leaves a half-taken step behind.

namespace froth {

/// Raise the flag (async-signal-safe).
void request_interrupt() noexcept;
/// True if an interrupt was requested; clears the flag.
bool consume_interrupt() noexcept;
/// True if an interrupt is pending; does not clear it.
bool interrupt_pending() noexcept;

} // namespace froth
