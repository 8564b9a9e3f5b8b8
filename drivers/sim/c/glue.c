/* SPDX-License-Identifier: Apache-2.0 */
/* glue.c: what the Rust tests call the C driver through. The driver's own
 * structs (drcc_dev, drcc_config) stay on the C side; Rust sees an opaque
 * handle and plain arguments, plus drcc_frame / drcc_bit_timing /
 * drcc_irq_result, which it mirrors with #[repr(C)]. */
#include <stdlib.h>

#include "drcc.h"

/* A new driver bound to the hooks, after drcc_init(); NULL and *rc on error. */
drcc_dev *sim_c_open(drcc_read32_fn read32, drcc_write32_fn write32, void *ctx, int *rc)
{
    drcc_dev *dev = malloc(sizeof *dev);
    if (dev == NULL) {
        *rc = DRCC_E_INVAL;
        return NULL;
    }
    *rc = drcc_init(dev, read32, write32, ctx);
    if (*rc != DRCC_OK) {
        free(dev);
        return NULL;
    }
    return dev;
}

/* Frees a driver from sim_c_open(). */
void sim_c_close(drcc_dev *dev) { free(dev); }

/* drcc_configure() with the bit timing computed by drcc_calc_bit_timing() and
 * the parameters the tests vary; the rest stays at drcc_config_default(). */
int sim_c_configure(drcc_dev *dev, uint32_t clock_hz, uint32_t bitrate, int mode, unsigned policy,
                    unsigned k, int dual_tx, uint16_t stall_limit, uint16_t recovery_bits,
                    uint16_t dedup_window, uint32_t int_enable)
{
    drcc_config cfg;
    int rc;
    drcc_config_default(&cfg);
    rc = drcc_calc_bit_timing(clock_hz, bitrate, &cfg.timing);
    if (rc != DRCC_OK) {
        return rc;
    }
    cfg.mode = (drcc_mode)mode;
    cfg.policy = policy;
    cfg.k = k;
    cfg.dual_tx = dual_tx;
    cfg.stall_limit = stall_limit;
    cfg.recovery_bits = recovery_bits;
    cfg.dedup_window = dedup_window;
    cfg.int_enable = int_enable;
    return drcc_configure(dev, &cfg);
}

/* STATS0 duplicates and STATS1 switches through drcc_get_stats(). */
void sim_c_stats(drcc_dev *dev, uint32_t *duplicates, uint32_t *switches)
{
    drcc_stats s;
    drcc_get_stats(dev, &s);
    *duplicates = s.duplicates;
    *switches = s.switches;
}
