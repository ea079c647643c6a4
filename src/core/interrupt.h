#pragma once
/// A process-wide "please stop" flag. The app's SIGINT handler raises it; long engine loops
/// (evolutions) poll it between steps, so Ctrl-C never leaves a half-taken step behind.

namespace froth {

/// Raise the flag (async-signal-safe); counts the requests since the last consume.
void request_interrupt() noexcept;
/// True if an interrupt was requested; clears the flag.
bool consume_interrupt() noexcept;
/// Requests since the flag was last consumed (a second Ctrl-C that nobody served yet: 2).
int interrupt_requests() noexcept;

/// Marks an engine loop that polls the flag between its steps. While one is active, other
/// listeners (the REPL's Lua hook inside an on_step callback) should leave a first request to
/// the loop, so Ctrl-C ends an evolution the same way with or without callbacks.
class EngineLoopScope {
  public:
    EngineLoopScope() noexcept;
    ~EngineLoopScope();
    EngineLoopScope(const EngineLoopScope&) = delete;
    EngineLoopScope& operator=(const EngineLoopScope&) = delete;
};
bool engine_loop_active() noexcept;

} // namespace froth
