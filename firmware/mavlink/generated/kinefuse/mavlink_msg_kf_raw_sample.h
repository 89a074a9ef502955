#pragma once
// MESSAGE KF_RAW_SAMPLE PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_KF_RAW_SAMPLE 52500


typedef struct __mavlink_kf_raw_sample_t {
 uint64_t time_boot_us; /*< [us] Time of the sample (sensor data-ready) on the unit's clock, microseconds since boot.*/
 uint32_t sample_counter; /*<  Sensor sample counter since boot (or since MAV_CMD_KF_STREAM with reset); wraps at 2^32. A gap means samples lost on the unit or on the link.*/
 int16_t acc_x; /*< [mG] Specific force along sensor x, 1 mG = 9.80665e-3 m/s^2 (a unit at rest with +z up reads acc_z = +1000).*/
 int16_t acc_y; /*< [mG] Specific force along sensor y, 1 mG = 9.80665e-3 m/s^2.*/
 int16_t acc_z; /*< [mG] Specific force along sensor z, 1 mG = 9.80665e-3 m/s^2.*/
 int16_t gyro_x; /*< [mrad/s] Angular rate about sensor x (right-hand rule), relative to inertial space.*/
 int16_t gyro_y; /*< [mrad/s] Angular rate about sensor y (right-hand rule), relative to inertial space.*/
 int16_t gyro_z; /*< [mrad/s] Angular rate about sensor z (right-hand rule), relative to inertial space.*/
 int16_t mag_x; /*< [mgauss] Magnetic flux density along sensor x, 1 mgauss = 0.1 uT.*/
 int16_t mag_y; /*< [mgauss] Magnetic flux density along sensor y, 1 mgauss = 0.1 uT.*/
 int16_t mag_z; /*< [mgauss] Magnetic flux density along sensor z, 1 mgauss = 0.1 uT.*/
 int16_t temperature; /*< [cdegC] Sensor die temperature (valid if KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID).*/
 uint8_t unit_id; /*<  Unit id (equals the MAVLink system id unless configured otherwise).*/
 uint8_t flags; /*<  Sample flags.*/
 uint8_t gyro_shift; /*<  Gyroscope range extension: gyro_x/y/z are in units of 2^gyro_shift mrad/s (gyro = gyro_raw * 2^gyro_shift * 1e-3 rad/s). The unit picks, per sample, the smallest shift 0..3 for which all three axes fit int16 after rounding (round half to even of the float64 quotient rate / (2^shift * 1e-3 rad/s)), so samples within +-32.767 rad/s keep 1 mrad/s resolution, send 0 (no bytes on the wire) and are unchanged; 1..3 extend the range to +-65.534, +-131.068, +-262.136 rad/s. A decoder without this field (or a recording made before it) reads 0. Samples taken from the unit's own sensor carry the sensor's counts: 0. In HIL mode 0 the calibration map still takes int16 1 mrad/s counts (saturated): a sample with gyro_shift above 0 sets KF_ORIENTATION_STATUS_INPUT_CLIPPED; HIL direct mode uses the float32 rates.*/
} mavlink_kf_raw_sample_t;

#define MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN 35
#define MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN 34
#define MAVLINK_MSG_ID_52500_LEN 35
#define MAVLINK_MSG_ID_52500_MIN_LEN 34

#define MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC 197
#define MAVLINK_MSG_ID_52500_CRC 197



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_KF_RAW_SAMPLE { \
    52500, \
    "KF_RAW_SAMPLE", \
    15, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_raw_sample_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_raw_sample_t, sample_counter) }, \
         { "acc_x", NULL, MAVLINK_TYPE_INT16_T, 0, 12, offsetof(mavlink_kf_raw_sample_t, acc_x) }, \
         { "acc_y", NULL, MAVLINK_TYPE_INT16_T, 0, 14, offsetof(mavlink_kf_raw_sample_t, acc_y) }, \
         { "acc_z", NULL, MAVLINK_TYPE_INT16_T, 0, 16, offsetof(mavlink_kf_raw_sample_t, acc_z) }, \
         { "gyro_x", NULL, MAVLINK_TYPE_INT16_T, 0, 18, offsetof(mavlink_kf_raw_sample_t, gyro_x) }, \
         { "gyro_y", NULL, MAVLINK_TYPE_INT16_T, 0, 20, offsetof(mavlink_kf_raw_sample_t, gyro_y) }, \
         { "gyro_z", NULL, MAVLINK_TYPE_INT16_T, 0, 22, offsetof(mavlink_kf_raw_sample_t, gyro_z) }, \
         { "mag_x", NULL, MAVLINK_TYPE_INT16_T, 0, 24, offsetof(mavlink_kf_raw_sample_t, mag_x) }, \
         { "mag_y", NULL, MAVLINK_TYPE_INT16_T, 0, 26, offsetof(mavlink_kf_raw_sample_t, mag_y) }, \
         { "mag_z", NULL, MAVLINK_TYPE_INT16_T, 0, 28, offsetof(mavlink_kf_raw_sample_t, mag_z) }, \
         { "temperature", NULL, MAVLINK_TYPE_INT16_T, 0, 30, offsetof(mavlink_kf_raw_sample_t, temperature) }, \
         { "unit_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 32, offsetof(mavlink_kf_raw_sample_t, unit_id) }, \
         { "flags", NULL, MAVLINK_TYPE_UINT8_T, 0, 33, offsetof(mavlink_kf_raw_sample_t, flags) }, \
         { "gyro_shift", NULL, MAVLINK_TYPE_UINT8_T, 0, 34, offsetof(mavlink_kf_raw_sample_t, gyro_shift) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_KF_RAW_SAMPLE { \
    "KF_RAW_SAMPLE", \
    15, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_raw_sample_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_raw_sample_t, sample_counter) }, \
         { "acc_x", NULL, MAVLINK_TYPE_INT16_T, 0, 12, offsetof(mavlink_kf_raw_sample_t, acc_x) }, \
         { "acc_y", NULL, MAVLINK_TYPE_INT16_T, 0, 14, offsetof(mavlink_kf_raw_sample_t, acc_y) }, \
         { "acc_z", NULL, MAVLINK_TYPE_INT16_T, 0, 16, offsetof(mavlink_kf_raw_sample_t, acc_z) }, \
         { "gyro_x", NULL, MAVLINK_TYPE_INT16_T, 0, 18, offsetof(mavlink_kf_raw_sample_t, gyro_x) }, \
         { "gyro_y", NULL, MAVLINK_TYPE_INT16_T, 0, 20, offsetof(mavlink_kf_raw_sample_t, gyro_y) }, \
         { "gyro_z", NULL, MAVLINK_TYPE_INT16_T, 0, 22, offsetof(mavlink_kf_raw_sample_t, gyro_z) }, \
         { "mag_x", NULL, MAVLINK_TYPE_INT16_T, 0, 24, offsetof(mavlink_kf_raw_sample_t, mag_x) }, \
         { "mag_y", NULL, MAVLINK_TYPE_INT16_T, 0, 26, offsetof(mavlink_kf_raw_sample_t, mag_y) }, \
         { "mag_z", NULL, MAVLINK_TYPE_INT16_T, 0, 28, offsetof(mavlink_kf_raw_sample_t, mag_z) }, \
         { "temperature", NULL, MAVLINK_TYPE_INT16_T, 0, 30, offsetof(mavlink_kf_raw_sample_t, temperature) }, \
         { "unit_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 32, offsetof(mavlink_kf_raw_sample_t, unit_id) }, \
         { "flags", NULL, MAVLINK_TYPE_UINT8_T, 0, 33, offsetof(mavlink_kf_raw_sample_t, flags) }, \
         { "gyro_shift", NULL, MAVLINK_TYPE_UINT8_T, 0, 34, offsetof(mavlink_kf_raw_sample_t, gyro_shift) }, \
         } \
}
#endif

/**
 * @brief Pack a kf_raw_sample message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the sample (sensor data-ready) on the unit's clock, microseconds since boot.
 * @param sample_counter  Sensor sample counter since boot (or since MAV_CMD_KF_STREAM with reset); wraps at 2^32. A gap means samples lost on the unit or on the link.
 * @param acc_x [mG] Specific force along sensor x, 1 mG = 9.80665e-3 m/s^2 (a unit at rest with +z up reads acc_z = +1000).
 * @param acc_y [mG] Specific force along sensor y, 1 mG = 9.80665e-3 m/s^2.
 * @param acc_z [mG] Specific force along sensor z, 1 mG = 9.80665e-3 m/s^2.
 * @param gyro_x [mrad/s] Angular rate about sensor x (right-hand rule), relative to inertial space.
 * @param gyro_y [mrad/s] Angular rate about sensor y (right-hand rule), relative to inertial space.
 * @param gyro_z [mrad/s] Angular rate about sensor z (right-hand rule), relative to inertial space.
 * @param mag_x [mgauss] Magnetic flux density along sensor x, 1 mgauss = 0.1 uT.
 * @param mag_y [mgauss] Magnetic flux density along sensor y, 1 mgauss = 0.1 uT.
 * @param mag_z [mgauss] Magnetic flux density along sensor z, 1 mgauss = 0.1 uT.
 * @param temperature [cdegC] Sensor die temperature (valid if KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID).
 * @param unit_id  Unit id (equals the MAVLink system id unless configured otherwise).
 * @param flags  Sample flags.
 * @param gyro_shift  Gyroscope range extension: gyro_x/y/z are in units of 2^gyro_shift mrad/s (gyro = gyro_raw * 2^gyro_shift * 1e-3 rad/s). The unit picks, per sample, the smallest shift 0..3 for which all three axes fit int16 after rounding (round half to even of the float64 quotient rate / (2^shift * 1e-3 rad/s)), so samples within +-32.767 rad/s keep 1 mrad/s resolution, send 0 (no bytes on the wire) and are unchanged; 1..3 extend the range to +-65.534, +-131.068, +-262.136 rad/s. A decoder without this field (or a recording made before it) reads 0. Samples taken from the unit's own sensor carry the sensor's counts: 0. In HIL mode 0 the calibration map still takes int16 1 mrad/s counts (saturated): a sample with gyro_shift above 0 sets KF_ORIENTATION_STATUS_INPUT_CLIPPED; HIL direct mode uses the float32 rates.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_raw_sample_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, int16_t acc_x, int16_t acc_y, int16_t acc_z, int16_t gyro_x, int16_t gyro_y, int16_t gyro_z, int16_t mag_x, int16_t mag_y, int16_t mag_z, int16_t temperature, uint8_t unit_id, uint8_t flags, uint8_t gyro_shift)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_int16_t(buf, 12, acc_x);
    _mav_put_int16_t(buf, 14, acc_y);
    _mav_put_int16_t(buf, 16, acc_z);
    _mav_put_int16_t(buf, 18, gyro_x);
    _mav_put_int16_t(buf, 20, gyro_y);
    _mav_put_int16_t(buf, 22, gyro_z);
    _mav_put_int16_t(buf, 24, mag_x);
    _mav_put_int16_t(buf, 26, mag_y);
    _mav_put_int16_t(buf, 28, mag_z);
    _mav_put_int16_t(buf, 30, temperature);
    _mav_put_uint8_t(buf, 32, unit_id);
    _mav_put_uint8_t(buf, 33, flags);
    _mav_put_uint8_t(buf, 34, gyro_shift);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#else
    mavlink_kf_raw_sample_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.acc_x = acc_x;
    packet.acc_y = acc_y;
    packet.acc_z = acc_z;
    packet.gyro_x = gyro_x;
    packet.gyro_y = gyro_y;
    packet.gyro_z = gyro_z;
    packet.mag_x = mag_x;
    packet.mag_y = mag_y;
    packet.mag_z = mag_z;
    packet.temperature = temperature;
    packet.unit_id = unit_id;
    packet.flags = flags;
    packet.gyro_shift = gyro_shift;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_RAW_SAMPLE;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
}

/**
 * @brief Pack a kf_raw_sample message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the sample (sensor data-ready) on the unit's clock, microseconds since boot.
 * @param sample_counter  Sensor sample counter since boot (or since MAV_CMD_KF_STREAM with reset); wraps at 2^32. A gap means samples lost on the unit or on the link.
 * @param acc_x [mG] Specific force along sensor x, 1 mG = 9.80665e-3 m/s^2 (a unit at rest with +z up reads acc_z = +1000).
 * @param acc_y [mG] Specific force along sensor y, 1 mG = 9.80665e-3 m/s^2.
 * @param acc_z [mG] Specific force along sensor z, 1 mG = 9.80665e-3 m/s^2.
 * @param gyro_x [mrad/s] Angular rate about sensor x (right-hand rule), relative to inertial space.
 * @param gyro_y [mrad/s] Angular rate about sensor y (right-hand rule), relative to inertial space.
 * @param gyro_z [mrad/s] Angular rate about sensor z (right-hand rule), relative to inertial space.
 * @param mag_x [mgauss] Magnetic flux density along sensor x, 1 mgauss = 0.1 uT.
 * @param mag_y [mgauss] Magnetic flux density along sensor y, 1 mgauss = 0.1 uT.
 * @param mag_z [mgauss] Magnetic flux density along sensor z, 1 mgauss = 0.1 uT.
 * @param temperature [cdegC] Sensor die temperature (valid if KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID).
 * @param unit_id  Unit id (equals the MAVLink system id unless configured otherwise).
 * @param flags  Sample flags.
 * @param gyro_shift  Gyroscope range extension: gyro_x/y/z are in units of 2^gyro_shift mrad/s (gyro = gyro_raw * 2^gyro_shift * 1e-3 rad/s). The unit picks, per sample, the smallest shift 0..3 for which all three axes fit int16 after rounding (round half to even of the float64 quotient rate / (2^shift * 1e-3 rad/s)), so samples within +-32.767 rad/s keep 1 mrad/s resolution, send 0 (no bytes on the wire) and are unchanged; 1..3 extend the range to +-65.534, +-131.068, +-262.136 rad/s. A decoder without this field (or a recording made before it) reads 0. Samples taken from the unit's own sensor carry the sensor's counts: 0. In HIL mode 0 the calibration map still takes int16 1 mrad/s counts (saturated): a sample with gyro_shift above 0 sets KF_ORIENTATION_STATUS_INPUT_CLIPPED; HIL direct mode uses the float32 rates.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_raw_sample_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, int16_t acc_x, int16_t acc_y, int16_t acc_z, int16_t gyro_x, int16_t gyro_y, int16_t gyro_z, int16_t mag_x, int16_t mag_y, int16_t mag_z, int16_t temperature, uint8_t unit_id, uint8_t flags, uint8_t gyro_shift)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_int16_t(buf, 12, acc_x);
    _mav_put_int16_t(buf, 14, acc_y);
    _mav_put_int16_t(buf, 16, acc_z);
    _mav_put_int16_t(buf, 18, gyro_x);
    _mav_put_int16_t(buf, 20, gyro_y);
    _mav_put_int16_t(buf, 22, gyro_z);
    _mav_put_int16_t(buf, 24, mag_x);
    _mav_put_int16_t(buf, 26, mag_y);
    _mav_put_int16_t(buf, 28, mag_z);
    _mav_put_int16_t(buf, 30, temperature);
    _mav_put_uint8_t(buf, 32, unit_id);
    _mav_put_uint8_t(buf, 33, flags);
    _mav_put_uint8_t(buf, 34, gyro_shift);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#else
    mavlink_kf_raw_sample_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.acc_x = acc_x;
    packet.acc_y = acc_y;
    packet.acc_z = acc_z;
    packet.gyro_x = gyro_x;
    packet.gyro_y = gyro_y;
    packet.gyro_z = gyro_z;
    packet.mag_x = mag_x;
    packet.mag_y = mag_y;
    packet.mag_z = mag_z;
    packet.temperature = temperature;
    packet.unit_id = unit_id;
    packet.flags = flags;
    packet.gyro_shift = gyro_shift;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_RAW_SAMPLE;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#endif
}

/**
 * @brief Pack a kf_raw_sample message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param time_boot_us [us] Time of the sample (sensor data-ready) on the unit's clock, microseconds since boot.
 * @param sample_counter  Sensor sample counter since boot (or since MAV_CMD_KF_STREAM with reset); wraps at 2^32. A gap means samples lost on the unit or on the link.
 * @param acc_x [mG] Specific force along sensor x, 1 mG = 9.80665e-3 m/s^2 (a unit at rest with +z up reads acc_z = +1000).
 * @param acc_y [mG] Specific force along sensor y, 1 mG = 9.80665e-3 m/s^2.
 * @param acc_z [mG] Specific force along sensor z, 1 mG = 9.80665e-3 m/s^2.
 * @param gyro_x [mrad/s] Angular rate about sensor x (right-hand rule), relative to inertial space.
 * @param gyro_y [mrad/s] Angular rate about sensor y (right-hand rule), relative to inertial space.
 * @param gyro_z [mrad/s] Angular rate about sensor z (right-hand rule), relative to inertial space.
 * @param mag_x [mgauss] Magnetic flux density along sensor x, 1 mgauss = 0.1 uT.
 * @param mag_y [mgauss] Magnetic flux density along sensor y, 1 mgauss = 0.1 uT.
 * @param mag_z [mgauss] Magnetic flux density along sensor z, 1 mgauss = 0.1 uT.
 * @param temperature [cdegC] Sensor die temperature (valid if KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID).
 * @param unit_id  Unit id (equals the MAVLink system id unless configured otherwise).
 * @param flags  Sample flags.
 * @param gyro_shift  Gyroscope range extension: gyro_x/y/z are in units of 2^gyro_shift mrad/s (gyro = gyro_raw * 2^gyro_shift * 1e-3 rad/s). The unit picks, per sample, the smallest shift 0..3 for which all three axes fit int16 after rounding (round half to even of the float64 quotient rate / (2^shift * 1e-3 rad/s)), so samples within +-32.767 rad/s keep 1 mrad/s resolution, send 0 (no bytes on the wire) and are unchanged; 1..3 extend the range to +-65.534, +-131.068, +-262.136 rad/s. A decoder without this field (or a recording made before it) reads 0. Samples taken from the unit's own sensor carry the sensor's counts: 0. In HIL mode 0 the calibration map still takes int16 1 mrad/s counts (saturated): a sample with gyro_shift above 0 sets KF_ORIENTATION_STATUS_INPUT_CLIPPED; HIL direct mode uses the float32 rates.
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_raw_sample_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint64_t time_boot_us,uint32_t sample_counter,int16_t acc_x,int16_t acc_y,int16_t acc_z,int16_t gyro_x,int16_t gyro_y,int16_t gyro_z,int16_t mag_x,int16_t mag_y,int16_t mag_z,int16_t temperature,uint8_t unit_id,uint8_t flags,uint8_t gyro_shift)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_int16_t(buf, 12, acc_x);
    _mav_put_int16_t(buf, 14, acc_y);
    _mav_put_int16_t(buf, 16, acc_z);
    _mav_put_int16_t(buf, 18, gyro_x);
    _mav_put_int16_t(buf, 20, gyro_y);
    _mav_put_int16_t(buf, 22, gyro_z);
    _mav_put_int16_t(buf, 24, mag_x);
    _mav_put_int16_t(buf, 26, mag_y);
    _mav_put_int16_t(buf, 28, mag_z);
    _mav_put_int16_t(buf, 30, temperature);
    _mav_put_uint8_t(buf, 32, unit_id);
    _mav_put_uint8_t(buf, 33, flags);
    _mav_put_uint8_t(buf, 34, gyro_shift);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#else
    mavlink_kf_raw_sample_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.acc_x = acc_x;
    packet.acc_y = acc_y;
    packet.acc_z = acc_z;
    packet.gyro_x = gyro_x;
    packet.gyro_y = gyro_y;
    packet.gyro_z = gyro_z;
    packet.mag_x = mag_x;
    packet.mag_y = mag_y;
    packet.mag_z = mag_z;
    packet.temperature = temperature;
    packet.unit_id = unit_id;
    packet.flags = flags;
    packet.gyro_shift = gyro_shift;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_RAW_SAMPLE;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
}

/**
 * @brief Encode a kf_raw_sample struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param kf_raw_sample C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_raw_sample_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_kf_raw_sample_t* kf_raw_sample)
{
    return mavlink_msg_kf_raw_sample_pack(system_id, component_id, msg, kf_raw_sample->time_boot_us, kf_raw_sample->sample_counter, kf_raw_sample->acc_x, kf_raw_sample->acc_y, kf_raw_sample->acc_z, kf_raw_sample->gyro_x, kf_raw_sample->gyro_y, kf_raw_sample->gyro_z, kf_raw_sample->mag_x, kf_raw_sample->mag_y, kf_raw_sample->mag_z, kf_raw_sample->temperature, kf_raw_sample->unit_id, kf_raw_sample->flags, kf_raw_sample->gyro_shift);
}

/**
 * @brief Encode a kf_raw_sample struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param kf_raw_sample C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_raw_sample_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_kf_raw_sample_t* kf_raw_sample)
{
    return mavlink_msg_kf_raw_sample_pack_chan(system_id, component_id, chan, msg, kf_raw_sample->time_boot_us, kf_raw_sample->sample_counter, kf_raw_sample->acc_x, kf_raw_sample->acc_y, kf_raw_sample->acc_z, kf_raw_sample->gyro_x, kf_raw_sample->gyro_y, kf_raw_sample->gyro_z, kf_raw_sample->mag_x, kf_raw_sample->mag_y, kf_raw_sample->mag_z, kf_raw_sample->temperature, kf_raw_sample->unit_id, kf_raw_sample->flags, kf_raw_sample->gyro_shift);
}

/**
 * @brief Encode a kf_raw_sample struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param kf_raw_sample C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_raw_sample_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_kf_raw_sample_t* kf_raw_sample)
{
    return mavlink_msg_kf_raw_sample_pack_status(system_id, component_id, _status, msg,  kf_raw_sample->time_boot_us, kf_raw_sample->sample_counter, kf_raw_sample->acc_x, kf_raw_sample->acc_y, kf_raw_sample->acc_z, kf_raw_sample->gyro_x, kf_raw_sample->gyro_y, kf_raw_sample->gyro_z, kf_raw_sample->mag_x, kf_raw_sample->mag_y, kf_raw_sample->mag_z, kf_raw_sample->temperature, kf_raw_sample->unit_id, kf_raw_sample->flags, kf_raw_sample->gyro_shift);
}

/**
 * @brief Send a kf_raw_sample message
 * @param chan MAVLink channel to send the message
 *
 * @param time_boot_us [us] Time of the sample (sensor data-ready) on the unit's clock, microseconds since boot.
 * @param sample_counter  Sensor sample counter since boot (or since MAV_CMD_KF_STREAM with reset); wraps at 2^32. A gap means samples lost on the unit or on the link.
 * @param acc_x [mG] Specific force along sensor x, 1 mG = 9.80665e-3 m/s^2 (a unit at rest with +z up reads acc_z = +1000).
 * @param acc_y [mG] Specific force along sensor y, 1 mG = 9.80665e-3 m/s^2.
 * @param acc_z [mG] Specific force along sensor z, 1 mG = 9.80665e-3 m/s^2.
 * @param gyro_x [mrad/s] Angular rate about sensor x (right-hand rule), relative to inertial space.
 * @param gyro_y [mrad/s] Angular rate about sensor y (right-hand rule), relative to inertial space.
 * @param gyro_z [mrad/s] Angular rate about sensor z (right-hand rule), relative to inertial space.
 * @param mag_x [mgauss] Magnetic flux density along sensor x, 1 mgauss = 0.1 uT.
 * @param mag_y [mgauss] Magnetic flux density along sensor y, 1 mgauss = 0.1 uT.
 * @param mag_z [mgauss] Magnetic flux density along sensor z, 1 mgauss = 0.1 uT.
 * @param temperature [cdegC] Sensor die temperature (valid if KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID).
 * @param unit_id  Unit id (equals the MAVLink system id unless configured otherwise).
 * @param flags  Sample flags.
 * @param gyro_shift  Gyroscope range extension: gyro_x/y/z are in units of 2^gyro_shift mrad/s (gyro = gyro_raw * 2^gyro_shift * 1e-3 rad/s). The unit picks, per sample, the smallest shift 0..3 for which all three axes fit int16 after rounding (round half to even of the float64 quotient rate / (2^shift * 1e-3 rad/s)), so samples within +-32.767 rad/s keep 1 mrad/s resolution, send 0 (no bytes on the wire) and are unchanged; 1..3 extend the range to +-65.534, +-131.068, +-262.136 rad/s. A decoder without this field (or a recording made before it) reads 0. Samples taken from the unit's own sensor carry the sensor's counts: 0. In HIL mode 0 the calibration map still takes int16 1 mrad/s counts (saturated): a sample with gyro_shift above 0 sets KF_ORIENTATION_STATUS_INPUT_CLIPPED; HIL direct mode uses the float32 rates.
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_kf_raw_sample_send(mavlink_channel_t chan, uint64_t time_boot_us, uint32_t sample_counter, int16_t acc_x, int16_t acc_y, int16_t acc_z, int16_t gyro_x, int16_t gyro_y, int16_t gyro_z, int16_t mag_x, int16_t mag_y, int16_t mag_z, int16_t temperature, uint8_t unit_id, uint8_t flags, uint8_t gyro_shift)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_int16_t(buf, 12, acc_x);
    _mav_put_int16_t(buf, 14, acc_y);
    _mav_put_int16_t(buf, 16, acc_z);
    _mav_put_int16_t(buf, 18, gyro_x);
    _mav_put_int16_t(buf, 20, gyro_y);
    _mav_put_int16_t(buf, 22, gyro_z);
    _mav_put_int16_t(buf, 24, mag_x);
    _mav_put_int16_t(buf, 26, mag_y);
    _mav_put_int16_t(buf, 28, mag_z);
    _mav_put_int16_t(buf, 30, temperature);
    _mav_put_uint8_t(buf, 32, unit_id);
    _mav_put_uint8_t(buf, 33, flags);
    _mav_put_uint8_t(buf, 34, gyro_shift);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_RAW_SAMPLE, buf, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
#else
    mavlink_kf_raw_sample_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.acc_x = acc_x;
    packet.acc_y = acc_y;
    packet.acc_z = acc_z;
    packet.gyro_x = gyro_x;
    packet.gyro_y = gyro_y;
    packet.gyro_z = gyro_z;
    packet.mag_x = mag_x;
    packet.mag_y = mag_y;
    packet.mag_z = mag_z;
    packet.temperature = temperature;
    packet.unit_id = unit_id;
    packet.flags = flags;
    packet.gyro_shift = gyro_shift;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_RAW_SAMPLE, (const char *)&packet, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
#endif
}

/**
 * @brief Send a kf_raw_sample message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_kf_raw_sample_send_struct(mavlink_channel_t chan, const mavlink_kf_raw_sample_t* kf_raw_sample)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_kf_raw_sample_send(chan, kf_raw_sample->time_boot_us, kf_raw_sample->sample_counter, kf_raw_sample->acc_x, kf_raw_sample->acc_y, kf_raw_sample->acc_z, kf_raw_sample->gyro_x, kf_raw_sample->gyro_y, kf_raw_sample->gyro_z, kf_raw_sample->mag_x, kf_raw_sample->mag_y, kf_raw_sample->mag_z, kf_raw_sample->temperature, kf_raw_sample->unit_id, kf_raw_sample->flags, kf_raw_sample->gyro_shift);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_RAW_SAMPLE, (const char *)kf_raw_sample, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
#endif
}

#if MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_kf_raw_sample_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint64_t time_boot_us, uint32_t sample_counter, int16_t acc_x, int16_t acc_y, int16_t acc_z, int16_t gyro_x, int16_t gyro_y, int16_t gyro_z, int16_t mag_x, int16_t mag_y, int16_t mag_z, int16_t temperature, uint8_t unit_id, uint8_t flags, uint8_t gyro_shift)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_int16_t(buf, 12, acc_x);
    _mav_put_int16_t(buf, 14, acc_y);
    _mav_put_int16_t(buf, 16, acc_z);
    _mav_put_int16_t(buf, 18, gyro_x);
    _mav_put_int16_t(buf, 20, gyro_y);
    _mav_put_int16_t(buf, 22, gyro_z);
    _mav_put_int16_t(buf, 24, mag_x);
    _mav_put_int16_t(buf, 26, mag_y);
    _mav_put_int16_t(buf, 28, mag_z);
    _mav_put_int16_t(buf, 30, temperature);
    _mav_put_uint8_t(buf, 32, unit_id);
    _mav_put_uint8_t(buf, 33, flags);
    _mav_put_uint8_t(buf, 34, gyro_shift);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_RAW_SAMPLE, buf, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
#else
    mavlink_kf_raw_sample_t *packet = (mavlink_kf_raw_sample_t *)msgbuf;
    packet->time_boot_us = time_boot_us;
    packet->sample_counter = sample_counter;
    packet->acc_x = acc_x;
    packet->acc_y = acc_y;
    packet->acc_z = acc_z;
    packet->gyro_x = gyro_x;
    packet->gyro_y = gyro_y;
    packet->gyro_z = gyro_z;
    packet->mag_x = mag_x;
    packet->mag_y = mag_y;
    packet->mag_z = mag_z;
    packet->temperature = temperature;
    packet->unit_id = unit_id;
    packet->flags = flags;
    packet->gyro_shift = gyro_shift;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_RAW_SAMPLE, (const char *)packet, MAVLINK_MSG_ID_KF_RAW_SAMPLE_MIN_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN, MAVLINK_MSG_ID_KF_RAW_SAMPLE_CRC);
#endif
}
#endif

#endif

// MESSAGE KF_RAW_SAMPLE UNPACKING


/**
 * @brief Get field time_boot_us from kf_raw_sample message
 *
 * @return [us] Time of the sample (sensor data-ready) on the unit's clock, microseconds since boot.
 */
static inline uint64_t mavlink_msg_kf_raw_sample_get_time_boot_us(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint64_t(msg,  0);
}

/**
 * @brief Get field sample_counter from kf_raw_sample message
 *
 * @return  Sensor sample counter since boot (or since MAV_CMD_KF_STREAM with reset); wraps at 2^32. A gap means samples lost on the unit or on the link.
 */
static inline uint32_t mavlink_msg_kf_raw_sample_get_sample_counter(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Get field acc_x from kf_raw_sample message
 *
 * @return [mG] Specific force along sensor x, 1 mG = 9.80665e-3 m/s^2 (a unit at rest with +z up reads acc_z = +1000).
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_acc_x(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  12);
}

/**
 * @brief Get field acc_y from kf_raw_sample message
 *
 * @return [mG] Specific force along sensor y, 1 mG = 9.80665e-3 m/s^2.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_acc_y(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  14);
}

/**
 * @brief Get field acc_z from kf_raw_sample message
 *
 * @return [mG] Specific force along sensor z, 1 mG = 9.80665e-3 m/s^2.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_acc_z(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  16);
}

/**
 * @brief Get field gyro_x from kf_raw_sample message
 *
 * @return [mrad/s] Angular rate about sensor x (right-hand rule), relative to inertial space.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_gyro_x(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  18);
}

/**
 * @brief Get field gyro_y from kf_raw_sample message
 *
 * @return [mrad/s] Angular rate about sensor y (right-hand rule), relative to inertial space.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_gyro_y(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  20);
}

/**
 * @brief Get field gyro_z from kf_raw_sample message
 *
 * @return [mrad/s] Angular rate about sensor z (right-hand rule), relative to inertial space.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_gyro_z(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  22);
}

/**
 * @brief Get field mag_x from kf_raw_sample message
 *
 * @return [mgauss] Magnetic flux density along sensor x, 1 mgauss = 0.1 uT.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_mag_x(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  24);
}

/**
 * @brief Get field mag_y from kf_raw_sample message
 *
 * @return [mgauss] Magnetic flux density along sensor y, 1 mgauss = 0.1 uT.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_mag_y(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  26);
}

/**
 * @brief Get field mag_z from kf_raw_sample message
 *
 * @return [mgauss] Magnetic flux density along sensor z, 1 mgauss = 0.1 uT.
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_mag_z(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  28);
}

/**
 * @brief Get field temperature from kf_raw_sample message
 *
 * @return [cdegC] Sensor die temperature (valid if KF_RAW_SAMPLE_FLAGS_TEMPERATURE_VALID).
 */
static inline int16_t mavlink_msg_kf_raw_sample_get_temperature(const mavlink_message_t* msg)
{
    return _MAV_RETURN_int16_t(msg,  30);
}

/**
 * @brief Get field unit_id from kf_raw_sample message
 *
 * @return  Unit id (equals the MAVLink system id unless configured otherwise).
 */
static inline uint8_t mavlink_msg_kf_raw_sample_get_unit_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  32);
}

/**
 * @brief Get field flags from kf_raw_sample message
 *
 * @return  Sample flags.
 */
static inline uint8_t mavlink_msg_kf_raw_sample_get_flags(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  33);
}

/**
 * @brief Get field gyro_shift from kf_raw_sample message
 *
 * @return  Gyroscope range extension: gyro_x/y/z are in units of 2^gyro_shift mrad/s (gyro = gyro_raw * 2^gyro_shift * 1e-3 rad/s). The unit picks, per sample, the smallest shift 0..3 for which all three axes fit int16 after rounding (round half to even of the float64 quotient rate / (2^shift * 1e-3 rad/s)), so samples within +-32.767 rad/s keep 1 mrad/s resolution, send 0 (no bytes on the wire) and are unchanged; 1..3 extend the range to +-65.534, +-131.068, +-262.136 rad/s. A decoder without this field (or a recording made before it) reads 0. Samples taken from the unit's own sensor carry the sensor's counts: 0. In HIL mode 0 the calibration map still takes int16 1 mrad/s counts (saturated): a sample with gyro_shift above 0 sets KF_ORIENTATION_STATUS_INPUT_CLIPPED; HIL direct mode uses the float32 rates.
 */
static inline uint8_t mavlink_msg_kf_raw_sample_get_gyro_shift(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  34);
}

/**
 * @brief Decode a kf_raw_sample message into a struct
 *
 * @param msg The message to decode
 * @param kf_raw_sample C-struct to decode the message contents into
 */
static inline void mavlink_msg_kf_raw_sample_decode(const mavlink_message_t* msg, mavlink_kf_raw_sample_t* kf_raw_sample)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    kf_raw_sample->time_boot_us = mavlink_msg_kf_raw_sample_get_time_boot_us(msg);
    kf_raw_sample->sample_counter = mavlink_msg_kf_raw_sample_get_sample_counter(msg);
    kf_raw_sample->acc_x = mavlink_msg_kf_raw_sample_get_acc_x(msg);
    kf_raw_sample->acc_y = mavlink_msg_kf_raw_sample_get_acc_y(msg);
    kf_raw_sample->acc_z = mavlink_msg_kf_raw_sample_get_acc_z(msg);
    kf_raw_sample->gyro_x = mavlink_msg_kf_raw_sample_get_gyro_x(msg);
    kf_raw_sample->gyro_y = mavlink_msg_kf_raw_sample_get_gyro_y(msg);
    kf_raw_sample->gyro_z = mavlink_msg_kf_raw_sample_get_gyro_z(msg);
    kf_raw_sample->mag_x = mavlink_msg_kf_raw_sample_get_mag_x(msg);
    kf_raw_sample->mag_y = mavlink_msg_kf_raw_sample_get_mag_y(msg);
    kf_raw_sample->mag_z = mavlink_msg_kf_raw_sample_get_mag_z(msg);
    kf_raw_sample->temperature = mavlink_msg_kf_raw_sample_get_temperature(msg);
    kf_raw_sample->unit_id = mavlink_msg_kf_raw_sample_get_unit_id(msg);
    kf_raw_sample->flags = mavlink_msg_kf_raw_sample_get_flags(msg);
    kf_raw_sample->gyro_shift = mavlink_msg_kf_raw_sample_get_gyro_shift(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN? msg->len : MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN;
        memset(kf_raw_sample, 0, MAVLINK_MSG_ID_KF_RAW_SAMPLE_LEN);
    memcpy(kf_raw_sample, _MAV_PAYLOAD(msg), len);
#endif
}
