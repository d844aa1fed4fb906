// The abstraction level is one choice for every device and unit: defined once in core/.
#pragma once

#include "core/abstraction.h"
