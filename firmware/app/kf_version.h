/*
 * kf_version.h - firmware version reported in KF_UNIT_STATUS and AUTOPILOT_VERSION.
 */
#ifndef KF_VERSION_H
#define KF_VERSION_H

#define KF_FW_MAJOR 0u
#define KF_FW_MINOR 2u
#define KF_FW_PATCH 0u
#define KF_FW_TYPE  0u   /* FIRMWARE_VERSION_TYPE_DEV */
#define KF_FW_VERSION ((KF_FW_MAJOR << 24) | (KF_FW_MINOR << 16) | (KF_FW_PATCH << 8) | KF_FW_TYPE)

/* first 32 bits of the git commit, set by the build (-DKF_GIT_HASH=0x...) */
#ifndef KF_GIT_HASH
#define KF_GIT_HASH 0u
#endif

#endif /* KF_VERSION_H */
