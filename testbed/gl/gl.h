#pragma once
// The one include for GL calls: glad's core 4.5 loader. Function pointers are resolved at
// run time through the active context backend (see context.h), never linked directly.
#include <glad/gl.h>
