/* startup.S -- reset code of the vlbe Cortex-M4F test images (QEMU
   mps2-an386): the vector table at address 0, a reset handler that turns the
   FPU on and enters newlib's rdimon crt0 (_start: .bss cleared, semihosting
   set up, main called, exit()), and a fault handler that ends the QEMU run
   with a failure (semihosting SYS_EXIT, reason "run-time error").
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
    b _start

    .thumb_func
    .globl fault_handler
fault_handler:
    movs r0, #0x18              /* SYS_EXIT                                */
    ldr r1, =0x20023            /* ADP_Stopped_RunTimeErrorUnknown         */
    bkpt 0xab
    b .
