/* startup.S -- reset code of the vlbe Cortex-M4F test images (QEMU
   mps2-an386): the vector table at address 0, a reset handler that turns the
   FPU on and enters newlib's rdimon crt0 (_start: .bss cleared, semihosting
   set up, main called, exit()), and a fault handler that ends the QEMU run
   with a failure (semihosting SYS_EXIT, reason "run-time error").  With
   -DM4_BARE (the footprint image, linked -nostartfiles) no crt0: the reset
   handler clears .bss, calls main and ends the run itself.
   -- part of vlbe                                  SPDX-License-Identifier: MIT */
    .syntax unified
    .cpu cortex-m4
    .thumb

    .section .vectors, "a"
    .align 2
    .globl vectors
vectors:
    .word __stack               /* initial stack pointer (linker script)   */
    .word reset_handler         /* reset                                   */
    .word fault_handler         /* NMI                                     */
    .word fault_handler         /* HardFault (a vlbe trap ends up here)    */
    .word fault_handler         /* MemManage                               */
    .word fault_handler         /* BusFault                                */
    .word fault_handler         /* UsageFault                              */

    .text
    .thumb_func
    .globl reset_handler
reset_handler:
    /* CPACR (0xE000ED88): CP10 and CP11 full access, before any float
       instruction; DSB/ISB make the change visible to what follows */
    ldr r0, =0xE000ED88
    ldr r1, [r0]
    orr r1, r1, #(0xF << 20)
    str r1, [r0]
    dsb
    isb
#ifndef M4_BARE
    b _start                    /* rdimon crt0: .bss, semihosting, main, exit */
#else
    /* bare image (no crt0, no stdio): clear .bss, call main, exit with
       success when it returns 0 and through the fault path otherwise */
    ldr r0, =__bss_start__
    ldr r1, =__bss_end__
    movs r2, #0
1:  cmp r0, r1
    itt lo
    strlo r2, [r0], #4
    blo 1b
    bl main
    cmp r0, #0
    bne fault_handler
    movs r0, #0x18              /* SYS_EXIT                                */
    ldr r1, =0x20026            /* ADP_Stopped_ApplicationExit             */
    bkpt 0xab
    b .
#endif

    .thumb_func
    .globl fault_handler
fault_handler:
    movs r0, #0x18              /* SYS_EXIT                                */
    ldr r1, =0x20023            /* ADP_Stopped_RunTimeErrorUnknown         */
    bkpt 0xab
    b .
