#include "lander/multibody/lander_run.h"

namespace touchdown::lander {

const char* LanderEventName(LanderEventKind kind) { return NameIn(kLanderEventNames, kind); }

}  // namespace touchdown::lander
