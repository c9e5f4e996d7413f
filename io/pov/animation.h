// POV-Ray's animation clock: which frame of a sequence a scene is read for, and the values the
// language then gives clock, frame_number, initial_frame, final_frame, initial_clock,
// final_clock, clock_delta and clock_on. The rules are POV-Ray 3.7's (measured with povray):
// a sequence runs when final_frame differs from initial_frame; a frame's clock is
// initial_clock + (final_clock - initial_clock) * (frame - initial_frame) / span, span being
// final_frame - initial_frame (one more for a cyclic animation, whose reported final_frame is
// one more too); a still reads clock (POV-Ray's +K, 0 by default) with every other value 0.
#pragma once

#include <optional>
#include <string>

namespace sheaf::io::pov {

/// What a host asks for: POV-Ray's Initial_Frame, Final_Frame, Initial_Clock, Final_Clock,
/// Cyclic_Animation, the frame to read, and Clock (+K) for a still.
struct Animation {
    int initial_frame = 1, final_frame = 1;
    double initial_clock = 0, final_clock = 1;
    bool cyclic = false;
    std::optional<int> frame;    ///< the frame to read; initial_frame when not set
    std::optional<double> clock; ///< a still's clock; clock_on is 1 when set

    /// Whether this is a sequence of frames (final_frame differs from initial_frame).
    bool sequence() const { return final_frame != initial_frame; }
};

/// The language's values for one frame.
struct Clock {
    double clock = 0, initial_clock = 0, final_clock = 0, clock_delta = 0;
    int frame_number = 0, initial_frame = 0, final_frame = 0;
    bool clock_on = false;
};

/// Why `a` cannot be read ("final_frame 1 is below initial_frame 3", a frame outside the
/// sequence), or "" when it can.
std::string animation_problem(const Animation& a);

/// The values for `a`'s frame; `a` must have no animation_problem.
Clock clock_for(const Animation& a);

/// The value of the clock identifier `name` (clock, frame_number, ... clock_on), or nothing
/// when `name` is not one.
std::optional<double> clock_identifier(const Clock& c, const std::string& name);

} // namespace sheaf::io::pov
