#pragma once

// The generated message type yarn_tearing::BreakEvent (namespace = package name) has the same
// qualified name as the core's struct yarn_tearing::BreakEvent, so the two cannot be declared in
// one translation unit. This header declares the message's typedef as yarn_tearing::BreakEventMsg
// instead; everything else of the message (BreakEvent_<>, BreakEventPtr, its traits) is unchanged.
// Include the message only through this header.
#define BreakEvent BreakEventMsg
#include <yarn_tearing/BreakEvent.h>
#undef BreakEvent
