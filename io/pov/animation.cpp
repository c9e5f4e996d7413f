// POV-Ray's animation clock (see animation.h).
#include "io/pov/animation.h"

namespace sheaf::io::pov {

std::string animation_problem(const Animation& a) {
    if (a.final_frame < a.initial_frame)
        return "final_frame " + std::to_string(a.final_frame) + " is below initial_frame " +
               std::to_string(a.initial_frame);
    if (a.frame && (*a.frame < a.initial_frame || *a.frame > a.final_frame))
        return "frame " + std::to_string(*a.frame) + " is outside the sequence " +
               std::to_string(a.initial_frame) + ".." + std::to_string(a.final_frame);
    return "";
}

Clock clock_for(const Animation& a) {
    Clock c;
    if (!a.sequence()) { // a still: only the clock (and whether one was given)
        c.clock = a.clock.value_or(0);
        c.clock_on = a.clock.has_value();
        return c;
    }
    const int span = a.final_frame - a.initial_frame + (a.cyclic ? 1 : 0);
    c.frame_number = a.frame.value_or(a.initial_frame);
    c.initial_frame = a.initial_frame;
    c.final_frame = a.final_frame + (a.cyclic ? 1 : 0);
    c.initial_clock = a.initial_clock;
    c.final_clock = a.final_clock;
    c.clock_delta = (a.final_clock - a.initial_clock) / span;
    c.clock = a.initial_clock +
              (a.final_clock - a.initial_clock) * double(c.frame_number - a.initial_frame) / span;
    c.clock_on = true;
    return c;
}

std::optional<double> clock_identifier(const Clock& c, const std::string& name) {
    if (name == "clock") return c.clock;
    if (name == "frame_number") return c.frame_number;
    if (name == "initial_frame") return c.initial_frame;
    if (name == "final_frame") return c.final_frame;
    if (name == "initial_clock") return c.initial_clock;
    if (name == "final_clock") return c.final_clock;
    if (name == "clock_delta") return c.clock_delta;
    if (name == "clock_on") return c.clock_on ? 1 : 0;
    return std::nullopt;
}

} // namespace sheaf::io::pov
