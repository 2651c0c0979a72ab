#pragma once
// SIGINT and SIGTERM, caught while a run or a server lives so that it ends cleanly (final
// checkpoint, last frame, closed streams), then handled by default again.
namespace psph {

void catch_interrupts();    // clears any earlier one and installs the handler
void release_interrupts();  // default handling again
int caught_interrupt();     // the signal caught since catch_interrupts(), 0 if none

}  // namespace psph
