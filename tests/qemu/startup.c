/* startup.c - reset and fault handlers for the QEMU mps2 test image
 * (tests/qemu, mk/qemu.mk): copy .data, zero .bss, enable the FPU, open the
 * semihosting handles, run main() and exit with its status (QEMU passes it
 * through as its own exit status). A fault exits with status 99 instead of
 * hanging. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

extern uint32_t __data_start[], __data_end[], __data_load[], __bss_start[], __bss_end[];
extern uint32_t __stack_top[];
extern void initialise_monitor_handles(void);
int main(void);
void trk_fw_reset(void);
void trk_fw_fault(void);
void _init(void);
void _fini(void);

/* crti/crtn are not linked (-nostartfiles); newlib's exit() calls _fini */
void _init(void) {}
void _fini(void) {}

void trk_fw_reset(void)
{
    uint32_t *src = __data_load, *dst = __data_start;
    while (dst < __data_end) *dst++ = *src++;
    for (dst = __bss_start; dst < __bss_end; dst++) *dst = 0;
    /* CPACR (0xE000ED88): full access to CP10 and CP11 (the FPU) before any
     * floating-point instruction */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
    initialise_monitor_handles();
    exit(main());
}

void trk_fw_fault(void)
{
    fputs("trk-fw: fault (HardFault/MemManage/BusFault/UsageFault/NMI)\n", stderr);
    exit(99);
}

/* Cortex-M vector table: initial stack pointer, then the exception handlers. */
typedef void (*trk_fw_vector)(void);
__attribute__((section(".vectors"), used)) static const trk_fw_vector vectors[16] = {
    (trk_fw_vector)(uintptr_t)__stack_top, /* initial SP */
    trk_fw_reset,                          /* reset */
    trk_fw_fault,                          /* NMI */
    trk_fw_fault,                          /* HardFault */
    trk_fw_fault,                          /* MemManage */
    trk_fw_fault,                          /* BusFault */
    trk_fw_fault,                          /* UsageFault */
    0, 0, 0, 0,                            /* reserved */
    trk_fw_fault,                          /* SVCall */
    trk_fw_fault,                          /* DebugMonitor */
    0,                                     /* reserved */
    trk_fw_fault,                          /* PendSV */
    trk_fw_fault,                          /* SysTick */
};
