/* m4_base.c -- the size baseline of make check-m4: the startup, newlib's
   crt0 and stdio and the output helper of the M4 programs, no vlbe call
   beyond vlbe.h's inline basics.  Its text is subtracted from each
   program's to give the part that vlbe and the program's own set-up add.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
#include "m4_out.h"

int main(void)
{
    m4_val("one", -1, VLBE_R(1.0));
    m4_int("zero", 0);
    return m4_exit();
}
