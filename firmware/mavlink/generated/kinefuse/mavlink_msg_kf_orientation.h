#pragma once
// MESSAGE KF_ORIENTATION PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_KF_ORIENTATION 52501

MAVPACKED(
typedef struct __mavlink_kf_orientation_t {
 uint64_t time_boot_us; /*< [us] Time of the newest sample used, unit clock, microseconds since boot.*/
 uint32_t sample_counter; /*<  sample_counter of the newest KF_RAW_SAMPLE used.*/
 float q_w; /*<  Quaternion sensor to earth, scalar part (v_earth = q * v_sensor * conj(q)).*/
 float q_x; /*<  Quaternion sensor to earth, x.*/
 float q_y; /*<  Quaternion sensor to earth, y.*/
 float q_z; /*<  Quaternion sensor to earth, z.*/
 uint32_t rejected_samples; /*<  Samples the filter rejected since boot (non-finite or out-of-range input, time step out of range); wraps at 2^32.*/
 uint16_t status; /*<  Filter status bits.*/
 uint8_t earth_frame; /*<  Earth frame of the quaternion.*/
 uint8_t filter_id; /*<  Estimator that produced the quaternion.*/
 uint8_t unit_id; /*<  Unit id.*/
 float cov[6]; /*<  Covariance of the orientation error, rad^2: upper triangle row-major (xx, xy, xz, yy, yz, zz) of the small rotation vector e in the earth frame, q_true = exp(e/2) * q. All zero: not provided (and then costs no bytes on the wire).*/
}) mavlink_kf_orientation_t;

#define MAVLINK_MSG_ID_KF_ORIENTATION_LEN 61
#define MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN 37
#define MAVLINK_MSG_ID_52501_LEN 61
#define MAVLINK_MSG_ID_52501_MIN_LEN 37

#define MAVLINK_MSG_ID_KF_ORIENTATION_CRC 145
#define MAVLINK_MSG_ID_52501_CRC 145

#define MAVLINK_MSG_KF_ORIENTATION_FIELD_COV_LEN 6

#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_KF_ORIENTATION { \
    52501, \
    "KF_ORIENTATION", \
    12, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_orientation_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_orientation_t, sample_counter) }, \
         { "q_w", NULL, MAVLINK_TYPE_FLOAT, 0, 12, offsetof(mavlink_kf_orientation_t, q_w) }, \
         { "q_x", NULL, MAVLINK_TYPE_FLOAT, 0, 16, offsetof(mavlink_kf_orientation_t, q_x) }, \
         { "q_y", NULL, MAVLINK_TYPE_FLOAT, 0, 20, offsetof(mavlink_kf_orientation_t, q_y) }, \
         { "q_z", NULL, MAVLINK_TYPE_FLOAT, 0, 24, offsetof(mavlink_kf_orientation_t, q_z) }, \
         { "rejected_samples", NULL, MAVLINK_TYPE_UINT32_T, 0, 28, offsetof(mavlink_kf_orientation_t, rejected_samples) }, \
         { "status", NULL, MAVLINK_TYPE_UINT16_T, 0, 32, offsetof(mavlink_kf_orientation_t, status) }, \
         { "earth_frame", NULL, MAVLINK_TYPE_UINT8_T, 0, 34, offsetof(mavlink_kf_orientation_t, earth_frame) }, \
         { "filter_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 35, offsetof(mavlink_kf_orientation_t, filter_id) }, \
         { "unit_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 36, offsetof(mavlink_kf_orientation_t, unit_id) }, \
         { "cov", NULL, MAVLINK_TYPE_FLOAT, 6, 37, offsetof(mavlink_kf_orientation_t, cov) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_KF_ORIENTATION { \
    "KF_ORIENTATION", \
    12, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_orientation_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_orientation_t, sample_counter) }, \
         { "q_w", NULL, MAVLINK_TYPE_FLOAT, 0, 12, offsetof(mavlink_kf_orientation_t, q_w) }, \
         { "q_x", NULL, MAVLINK_TYPE_FLOAT, 0, 16, offsetof(mavlink_kf_orientation_t, q_x) }, \
         { "q_y", NULL, MAVLINK_TYPE_FLOAT, 0, 20, offsetof(mavlink_kf_orientation_t, q_y) }, \
         { "q_z", NULL, MAVLINK_TYPE_FLOAT, 0, 24, offsetof(mavlink_kf_orientation_t, q_z) }, \
         { "rejected_samples", NULL, MAVLINK_TYPE_UINT32_T, 0, 28, offsetof(mavlink_kf_orientation_t, rejected_samples) }, \
         { "status", NULL, MAVLINK_TYPE_UINT16_T, 0, 32, offsetof(mavlink_kf_orientation_t, status) }, \
         { "earth_frame", NULL, MAVLINK_TYPE_UINT8_T, 0, 34, offsetof(mavlink_kf_orientation_t, earth_frame) }, \
         { "filter_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 35, offsetof(mavlink_kf_orientation_t, filter_id) }, \
         { "unit_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 36, offsetof(mavlink_kf_orientation_t, unit_id) }, \
         { "cov", NULL, MAVLINK_TYPE_FLOAT, 6, 37, offsetof(mavlink_kf_orientation_t, cov) }, \
         } \
}
#endif

/**
 * @brief Pack a kf_orientation message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest KF_RAW_SAMPLE used.
 * @param q_w  Quaternion sensor to earth, scalar part (v_earth = q * v_sensor * conj(q)).
 * @param q_x  Quaternion sensor to earth, x.
 * @param q_y  Quaternion sensor to earth, y.
 * @param q_z  Quaternion sensor to earth, z.
 * @param rejected_samples  Samples the filter rejected since boot (non-finite or out-of-range input, time step out of range); wraps at 2^32.
 * @param status  Filter status bits.
 * @param earth_frame  Earth frame of the quaternion.
 * @param filter_id  Estimator that produced the quaternion.
 * @param unit_id  Unit id.
 * @param cov  Covariance of the orientation error, rad^2: upper triangle row-major (xx, xy, xz, yy, yz, zz) of the small rotation vector e in the earth frame, q_true = exp(e/2) * q. All zero: not provided (and then costs no bytes on the wire).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_orientation_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, float q_w, float q_x, float q_y, float q_z, uint32_t rejected_samples, uint16_t status, uint8_t earth_frame, uint8_t filter_id, uint8_t unit_id, const float *cov)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_ORIENTATION_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, q_w);
    _mav_put_float(buf, 16, q_x);
    _mav_put_float(buf, 20, q_y);
    _mav_put_float(buf, 24, q_z);
    _mav_put_uint32_t(buf, 28, rejected_samples);
    _mav_put_uint16_t(buf, 32, status);
    _mav_put_uint8_t(buf, 34, earth_frame);
    _mav_put_uint8_t(buf, 35, filter_id);
    _mav_put_uint8_t(buf, 36, unit_id);
    _mav_put_float_array(buf, 37, cov, 6);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#else
    mavlink_kf_orientation_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.q_w = q_w;
    packet.q_x = q_x;
    packet.q_y = q_y;
    packet.q_z = q_z;
    packet.rejected_samples = rejected_samples;
    packet.status = status;
    packet.earth_frame = earth_frame;
    packet.filter_id = filter_id;
    packet.unit_id = unit_id;
    mav_array_memcpy(packet.cov, cov, sizeof(float)*6);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_ORIENTATION;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
}

/**
 * @brief Pack a kf_orientation message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest KF_RAW_SAMPLE used.
 * @param q_w  Quaternion sensor to earth, scalar part (v_earth = q * v_sensor * conj(q)).
 * @param q_x  Quaternion sensor to earth, x.
 * @param q_y  Quaternion sensor to earth, y.
 * @param q_z  Quaternion sensor to earth, z.
 * @param rejected_samples  Samples the filter rejected since boot (non-finite or out-of-range input, time step out of range); wraps at 2^32.
 * @param status  Filter status bits.
 * @param earth_frame  Earth frame of the quaternion.
 * @param filter_id  Estimator that produced the quaternion.
 * @param unit_id  Unit id.
 * @param cov  Covariance of the orientation error, rad^2: upper triangle row-major (xx, xy, xz, yy, yz, zz) of the small rotation vector e in the earth frame, q_true = exp(e/2) * q. All zero: not provided (and then costs no bytes on the wire).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_orientation_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, float q_w, float q_x, float q_y, float q_z, uint32_t rejected_samples, uint16_t status, uint8_t earth_frame, uint8_t filter_id, uint8_t unit_id, const float *cov)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_ORIENTATION_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, q_w);
    _mav_put_float(buf, 16, q_x);
    _mav_put_float(buf, 20, q_y);
    _mav_put_float(buf, 24, q_z);
    _mav_put_uint32_t(buf, 28, rejected_samples);
    _mav_put_uint16_t(buf, 32, status);
    _mav_put_uint8_t(buf, 34, earth_frame);
    _mav_put_uint8_t(buf, 35, filter_id);
    _mav_put_uint8_t(buf, 36, unit_id);
    _mav_put_float_array(buf, 37, cov, 6);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#else
    mavlink_kf_orientation_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.q_w = q_w;
    packet.q_x = q_x;
    packet.q_y = q_y;
    packet.q_z = q_z;
    packet.rejected_samples = rejected_samples;
    packet.status = status;
    packet.earth_frame = earth_frame;
    packet.filter_id = filter_id;
    packet.unit_id = unit_id;
    mav_array_memcpy(packet.cov, cov, sizeof(float)*6);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_ORIENTATION;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#endif
}

/**
 * @brief Pack a kf_orientation message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest KF_RAW_SAMPLE used.
 * @param q_w  Quaternion sensor to earth, scalar part (v_earth = q * v_sensor * conj(q)).
 * @param q_x  Quaternion sensor to earth, x.
 * @param q_y  Quaternion sensor to earth, y.
 * @param q_z  Quaternion sensor to earth, z.
 * @param rejected_samples  Samples the filter rejected since boot (non-finite or out-of-range input, time step out of range); wraps at 2^32.
 * @param status  Filter status bits.
 * @param earth_frame  Earth frame of the quaternion.
 * @param filter_id  Estimator that produced the quaternion.
 * @param unit_id  Unit id.
 * @param cov  Covariance of the orientation error, rad^2: upper triangle row-major (xx, xy, xz, yy, yz, zz) of the small rotation vector e in the earth frame, q_true = exp(e/2) * q. All zero: not provided (and then costs no bytes on the wire).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_orientation_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint64_t time_boot_us,uint32_t sample_counter,float q_w,float q_x,float q_y,float q_z,uint32_t rejected_samples,uint16_t status,uint8_t earth_frame,uint8_t filter_id,uint8_t unit_id,const float *cov)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_ORIENTATION_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, q_w);
    _mav_put_float(buf, 16, q_x);
    _mav_put_float(buf, 20, q_y);
    _mav_put_float(buf, 24, q_z);
    _mav_put_uint32_t(buf, 28, rejected_samples);
    _mav_put_uint16_t(buf, 32, status);
    _mav_put_uint8_t(buf, 34, earth_frame);
    _mav_put_uint8_t(buf, 35, filter_id);
    _mav_put_uint8_t(buf, 36, unit_id);
    _mav_put_float_array(buf, 37, cov, 6);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#else
    mavlink_kf_orientation_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.q_w = q_w;
    packet.q_x = q_x;
    packet.q_y = q_y;
    packet.q_z = q_z;
    packet.rejected_samples = rejected_samples;
    packet.status = status;
    packet.earth_frame = earth_frame;
    packet.filter_id = filter_id;
    packet.unit_id = unit_id;
    mav_array_memcpy(packet.cov, cov, sizeof(float)*6);
        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_ORIENTATION;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
}

/**
 * @brief Encode a kf_orientation struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param kf_orientation C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_orientation_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_kf_orientation_t* kf_orientation)
{
    return mavlink_msg_kf_orientation_pack(system_id, component_id, msg, kf_orientation->time_boot_us, kf_orientation->sample_counter, kf_orientation->q_w, kf_orientation->q_x, kf_orientation->q_y, kf_orientation->q_z, kf_orientation->rejected_samples, kf_orientation->status, kf_orientation->earth_frame, kf_orientation->filter_id, kf_orientation->unit_id, kf_orientation->cov);
}

/**
 * @brief Encode a kf_orientation struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param kf_orientation C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_orientation_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_kf_orientation_t* kf_orientation)
{
    return mavlink_msg_kf_orientation_pack_chan(system_id, component_id, chan, msg, kf_orientation->time_boot_us, kf_orientation->sample_counter, kf_orientation->q_w, kf_orientation->q_x, kf_orientation->q_y, kf_orientation->q_z, kf_orientation->rejected_samples, kf_orientation->status, kf_orientation->earth_frame, kf_orientation->filter_id, kf_orientation->unit_id, kf_orientation->cov);
}

/**
 * @brief Encode a kf_orientation struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param kf_orientation C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_orientation_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_kf_orientation_t* kf_orientation)
{
    return mavlink_msg_kf_orientation_pack_status(system_id, component_id, _status, msg,  kf_orientation->time_boot_us, kf_orientation->sample_counter, kf_orientation->q_w, kf_orientation->q_x, kf_orientation->q_y, kf_orientation->q_z, kf_orientation->rejected_samples, kf_orientation->status, kf_orientation->earth_frame, kf_orientation->filter_id, kf_orientation->unit_id, kf_orientation->cov);
}

/**
 * @brief Send a kf_orientation message
 * @param chan MAVLink channel to send the message
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest KF_RAW_SAMPLE used.
 * @param q_w  Quaternion sensor to earth, scalar part (v_earth = q * v_sensor * conj(q)).
 * @param q_x  Quaternion sensor to earth, x.
 * @param q_y  Quaternion sensor to earth, y.
 * @param q_z  Quaternion sensor to earth, z.
 * @param rejected_samples  Samples the filter rejected since boot (non-finite or out-of-range input, time step out of range); wraps at 2^32.
 * @param status  Filter status bits.
 * @param earth_frame  Earth frame of the quaternion.
 * @param filter_id  Estimator that produced the quaternion.
 * @param unit_id  Unit id.
 * @param cov  Covariance of the orientation error, rad^2: upper triangle row-major (xx, xy, xz, yy, yz, zz) of the small rotation vector e in the earth frame, q_true = exp(e/2) * q. All zero: not provided (and then costs no bytes on the wire).
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_kf_orientation_send(mavlink_channel_t chan, uint64_t time_boot_us, uint32_t sample_counter, float q_w, float q_x, float q_y, float q_z, uint32_t rejected_samples, uint16_t status, uint8_t earth_frame, uint8_t filter_id, uint8_t unit_id, const float *cov)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_ORIENTATION_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, q_w);
    _mav_put_float(buf, 16, q_x);
    _mav_put_float(buf, 20, q_y);
    _mav_put_float(buf, 24, q_z);
    _mav_put_uint32_t(buf, 28, rejected_samples);
    _mav_put_uint16_t(buf, 32, status);
    _mav_put_uint8_t(buf, 34, earth_frame);
    _mav_put_uint8_t(buf, 35, filter_id);
    _mav_put_uint8_t(buf, 36, unit_id);
    _mav_put_float_array(buf, 37, cov, 6);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_ORIENTATION, buf, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
#else
    mavlink_kf_orientation_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.q_w = q_w;
    packet.q_x = q_x;
    packet.q_y = q_y;
    packet.q_z = q_z;
    packet.rejected_samples = rejected_samples;
    packet.status = status;
    packet.earth_frame = earth_frame;
    packet.filter_id = filter_id;
    packet.unit_id = unit_id;
    mav_array_memcpy(packet.cov, cov, sizeof(float)*6);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_ORIENTATION, (const char *)&packet, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
#endif
}

/**
 * @brief Send a kf_orientation message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_kf_orientation_send_struct(mavlink_channel_t chan, const mavlink_kf_orientation_t* kf_orientation)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_kf_orientation_send(chan, kf_orientation->time_boot_us, kf_orientation->sample_counter, kf_orientation->q_w, kf_orientation->q_x, kf_orientation->q_y, kf_orientation->q_z, kf_orientation->rejected_samples, kf_orientation->status, kf_orientation->earth_frame, kf_orientation->filter_id, kf_orientation->unit_id, kf_orientation->cov);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_ORIENTATION, (const char *)kf_orientation, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
#endif
}

#if MAVLINK_MSG_ID_KF_ORIENTATION_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_kf_orientation_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint64_t time_boot_us, uint32_t sample_counter, float q_w, float q_x, float q_y, float q_z, uint32_t rejected_samples, uint16_t status, uint8_t earth_frame, uint8_t filter_id, uint8_t unit_id, const float *cov)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, q_w);
    _mav_put_float(buf, 16, q_x);
    _mav_put_float(buf, 20, q_y);
    _mav_put_float(buf, 24, q_z);
    _mav_put_uint32_t(buf, 28, rejected_samples);
    _mav_put_uint16_t(buf, 32, status);
    _mav_put_uint8_t(buf, 34, earth_frame);
    _mav_put_uint8_t(buf, 35, filter_id);
    _mav_put_uint8_t(buf, 36, unit_id);
    _mav_put_float_array(buf, 37, cov, 6);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_ORIENTATION, buf, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
#else
    mavlink_kf_orientation_t *packet = (mavlink_kf_orientation_t *)msgbuf;
    packet->time_boot_us = time_boot_us;
    packet->sample_counter = sample_counter;
    packet->q_w = q_w;
    packet->q_x = q_x;
    packet->q_y = q_y;
    packet->q_z = q_z;
    packet->rejected_samples = rejected_samples;
    packet->status = status;
    packet->earth_frame = earth_frame;
    packet->filter_id = filter_id;
    packet->unit_id = unit_id;
    mav_array_memcpy(packet->cov, cov, sizeof(float)*6);
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_ORIENTATION, (const char *)packet, MAVLINK_MSG_ID_KF_ORIENTATION_MIN_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_LEN, MAVLINK_MSG_ID_KF_ORIENTATION_CRC);
#endif
}
#endif

#endif

// MESSAGE KF_ORIENTATION UNPACKING


/**
 * @brief Get field time_boot_us from kf_orientation message
 *
 * @return [us] Time of the newest sample used, unit clock, microseconds since boot.
 */
static inline uint64_t mavlink_msg_kf_orientation_get_time_boot_us(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint64_t(msg,  0);
}

/**
 * @brief Get field sample_counter from kf_orientation message
 *
 * @return  sample_counter of the newest KF_RAW_SAMPLE used.
 */
static inline uint32_t mavlink_msg_kf_orientation_get_sample_counter(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Get field q_w from kf_orientation message
 *
 * @return  Quaternion sensor to earth, scalar part (v_earth = q * v_sensor * conj(q)).
 */
static inline float mavlink_msg_kf_orientation_get_q_w(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  12);
}

/**
 * @brief Get field q_x from kf_orientation message
 *
 * @return  Quaternion sensor to earth, x.
 */
static inline float mavlink_msg_kf_orientation_get_q_x(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  16);
}

/**
 * @brief Get field q_y from kf_orientation message
 *
 * @return  Quaternion sensor to earth, y.
 */
static inline float mavlink_msg_kf_orientation_get_q_y(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  20);
}

/**
 * @brief Get field q_z from kf_orientation message
 *
 * @return  Quaternion sensor to earth, z.
 */
static inline float mavlink_msg_kf_orientation_get_q_z(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  24);
}

/**
 * @brief Get field rejected_samples from kf_orientation message
 *
 * @return  Samples the filter rejected since boot (non-finite or out-of-range input, time step out of range); wraps at 2^32.
 */
static inline uint32_t mavlink_msg_kf_orientation_get_rejected_samples(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  28);
}

/**
 * @brief Get field status from kf_orientation message
 *
 * @return  Filter status bits.
 */
static inline uint16_t mavlink_msg_kf_orientation_get_status(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint16_t(msg,  32);
}

/**
 * @brief Get field earth_frame from kf_orientation message
 *
 * @return  Earth frame of the quaternion.
 */
static inline uint8_t mavlink_msg_kf_orientation_get_earth_frame(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  34);
}

/**
 * @brief Get field filter_id from kf_orientation message
 *
 * @return  Estimator that produced the quaternion.
 */
static inline uint8_t mavlink_msg_kf_orientation_get_filter_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  35);
}

/**
 * @brief Get field unit_id from kf_orientation message
 *
 * @return  Unit id.
 */
static inline uint8_t mavlink_msg_kf_orientation_get_unit_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  36);
}

/**
 * @brief Get field cov from kf_orientation message
 *
 * @return  Covariance of the orientation error, rad^2: upper triangle row-major (xx, xy, xz, yy, yz, zz) of the small rotation vector e in the earth frame, q_true = exp(e/2) * q. All zero: not provided (and then costs no bytes on the wire).
 */
static inline uint16_t mavlink_msg_kf_orientation_get_cov(const mavlink_message_t* msg, float *cov)
{
    return _MAV_RETURN_float_array(msg, cov, 6,  37);
}

/**
 * @brief Decode a kf_orientation message into a struct
 *
 * @param msg The message to decode
 * @param kf_orientation C-struct to decode the message contents into
 */
static inline void mavlink_msg_kf_orientation_decode(const mavlink_message_t* msg, mavlink_kf_orientation_t* kf_orientation)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    kf_orientation->time_boot_us = mavlink_msg_kf_orientation_get_time_boot_us(msg);
    kf_orientation->sample_counter = mavlink_msg_kf_orientation_get_sample_counter(msg);
    kf_orientation->q_w = mavlink_msg_kf_orientation_get_q_w(msg);
    kf_orientation->q_x = mavlink_msg_kf_orientation_get_q_x(msg);
    kf_orientation->q_y = mavlink_msg_kf_orientation_get_q_y(msg);
    kf_orientation->q_z = mavlink_msg_kf_orientation_get_q_z(msg);
    kf_orientation->rejected_samples = mavlink_msg_kf_orientation_get_rejected_samples(msg);
    kf_orientation->status = mavlink_msg_kf_orientation_get_status(msg);
    kf_orientation->earth_frame = mavlink_msg_kf_orientation_get_earth_frame(msg);
    kf_orientation->filter_id = mavlink_msg_kf_orientation_get_filter_id(msg);
    kf_orientation->unit_id = mavlink_msg_kf_orientation_get_unit_id(msg);
    mavlink_msg_kf_orientation_get_cov(msg, kf_orientation->cov);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_KF_ORIENTATION_LEN? msg->len : MAVLINK_MSG_ID_KF_ORIENTATION_LEN;
        memset(kf_orientation, 0, MAVLINK_MSG_ID_KF_ORIENTATION_LEN);
    memcpy(kf_orientation, _MAV_PAYLOAD(msg), len);
#endif
}
