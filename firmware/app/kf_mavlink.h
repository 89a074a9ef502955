/*
 * kf_mavlink.h - the generated MAVLink C headers (kinefuse dialect) as the application uses
 * them: one link, MAVLink 2 only, messages packed with the *_pack_status() functions on an
 * explicit mavlink_status_t (no channel globals of the library are used).
 *
 * Build with -isystem firmware/mavlink/generated (mavgen's C is not -Wextra clean).
 */
#ifndef KF_MAVLINK_H
#define KF_MAVLINK_H

#define MAVLINK_COMM_NUM_BUFFERS 1
#include "kinefuse/mavlink.h"
#include "kf_dialect.h"

#define KF_FRAME_MAX (MAVLINK_NUM_NON_PAYLOAD_BYTES + MAVLINK_MAX_PAYLOAD_LEN + MAVLINK_SIGNATURE_BLOCK_LEN)
#define KF_COMPONENT_ID MAV_COMP_ID_IMU

#endif /* KF_MAVLINK_H */
