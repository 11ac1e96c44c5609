/* startup.c - reset and fault handlers of a bare-metal Cortex-M4F image
 * (QEMU's mps2-an386 board, linker script mps2-an386.ld): copy .data from its
 * load image, zero .bss, enable the FPU, open the semihosting handles, run
 * main() and exit with its status. Under QEMU with -semihosting the exit
 * status becomes QEMU's own; on a board without a debugger attached, replace
 * exit() by whatever the product does when main returns. A fault exits with
 * status 99 instead of hanging. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* from the linker script */
extern uint32_t __data_start[], __data_end[], __data_load[], __bss_start[], __bss_end[];
extern uint32_t __stack_top[];
/* newlib's semihosting library (rdimon.specs): stdin/stdout/stderr */
extern void initialise_monitor_handles(void);
int main(void);
void fw_reset(void);
void fw_fault(void);
void _init(void);
void _fini(void);

/* crti/crtn are not linked (-nostartfiles); newlib's exit() calls _fini */
void _init(void) {}
void _fini(void) {}

void fw_reset(void)
{
    uint32_t *src = __data_load, *dst = __data_start;
    while (dst < __data_end) *dst++ = *src++;
    for (dst = __bss_start; dst < __bss_end; dst++) *dst = 0;
    /* CPACR (0xE000ED88): full access to CP10 and CP11, the FPU, before the
     * first floating-point instruction (the library is built for the
     * hard-float ABI: every call passes floats in FPU registers) */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    initialise_monitor_handles();
    exit(main());
}

void fw_fault(void)
{
    fputs("fault (HardFault/MemManage/BusFault/UsageFault/NMI)\n", stderr);
    exit(99);
}

/* Cortex-M vector table at address 0: initial stack pointer, then the
 * exception handlers (no device interrupts used) */
typedef void (*fw_vector)(void);
__attribute__((section(".vectors"), used)) static const fw_vector vectors[16] = {
    (fw_vector)(uintptr_t)__stack_top, /* initial SP */
    fw_reset,                          /* reset */
    fw_fault,                          /* NMI */
    fw_fault,                          /* HardFault */
    fw_fault,                          /* MemManage */
    fw_fault,                          /* BusFault */
    fw_fault,                          /* UsageFault */
    0, 0, 0, 0,                        /* reserved */
    fw_fault,                          /* SVCall */
    fw_fault,                          /* DebugMonitor */
    0,                                 /* reserved */
    fw_fault,                          /* PendSV */
    fw_fault,                          /* SysTick */
};
