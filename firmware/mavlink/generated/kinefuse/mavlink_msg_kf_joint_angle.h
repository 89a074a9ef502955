#pragma once
// MESSAGE KF_JOINT_ANGLE PACKING

#include <stdint.h>

#define MAVLINK_MSG_ID_KF_JOINT_ANGLE 52502


typedef struct __mavlink_kf_joint_angle_t {
 uint64_t time_boot_us; /*< [us] Time of the newest sample used, unit clock, microseconds since boot.*/
 uint32_t sample_counter; /*<  sample_counter of the newest sample used (of the sending unit).*/
 float angle_1; /*< [rad] First angle of the sequence (about the first axis, proximal frame).*/
 float angle_2; /*< [rad] Second angle of the sequence (floating axis).*/
 float angle_3; /*< [rad] Third angle of the sequence (about the last axis, distal frame).*/
 uint8_t joint_id; /*<  Joint.*/
 uint8_t sequence; /*<  Decomposition sequence of angle_1..3.*/
 uint8_t status; /*<  Status bits.*/
 uint8_t proximal_unit; /*<  Unit id on the proximal segment (0: not a unit).*/
 uint8_t distal_unit; /*<  Unit id on the distal segment (0: not a unit).*/
} mavlink_kf_joint_angle_t;

#define MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN 29
#define MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN 29
#define MAVLINK_MSG_ID_52502_LEN 29
#define MAVLINK_MSG_ID_52502_MIN_LEN 29

#define MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC 18
#define MAVLINK_MSG_ID_52502_CRC 18



#if MAVLINK_COMMAND_24BIT
#define MAVLINK_MESSAGE_INFO_KF_JOINT_ANGLE { \
    52502, \
    "KF_JOINT_ANGLE", \
    10, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_joint_angle_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_joint_angle_t, sample_counter) }, \
         { "angle_1", NULL, MAVLINK_TYPE_FLOAT, 0, 12, offsetof(mavlink_kf_joint_angle_t, angle_1) }, \
         { "angle_2", NULL, MAVLINK_TYPE_FLOAT, 0, 16, offsetof(mavlink_kf_joint_angle_t, angle_2) }, \
         { "angle_3", NULL, MAVLINK_TYPE_FLOAT, 0, 20, offsetof(mavlink_kf_joint_angle_t, angle_3) }, \
         { "joint_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 24, offsetof(mavlink_kf_joint_angle_t, joint_id) }, \
         { "sequence", NULL, MAVLINK_TYPE_UINT8_T, 0, 25, offsetof(mavlink_kf_joint_angle_t, sequence) }, \
         { "status", NULL, MAVLINK_TYPE_UINT8_T, 0, 26, offsetof(mavlink_kf_joint_angle_t, status) }, \
         { "proximal_unit", NULL, MAVLINK_TYPE_UINT8_T, 0, 27, offsetof(mavlink_kf_joint_angle_t, proximal_unit) }, \
         { "distal_unit", NULL, MAVLINK_TYPE_UINT8_T, 0, 28, offsetof(mavlink_kf_joint_angle_t, distal_unit) }, \
         } \
}
#else
#define MAVLINK_MESSAGE_INFO_KF_JOINT_ANGLE { \
    "KF_JOINT_ANGLE", \
    10, \
    {  { "time_boot_us", NULL, MAVLINK_TYPE_UINT64_T, 0, 0, offsetof(mavlink_kf_joint_angle_t, time_boot_us) }, \
         { "sample_counter", NULL, MAVLINK_TYPE_UINT32_T, 0, 8, offsetof(mavlink_kf_joint_angle_t, sample_counter) }, \
         { "angle_1", NULL, MAVLINK_TYPE_FLOAT, 0, 12, offsetof(mavlink_kf_joint_angle_t, angle_1) }, \
         { "angle_2", NULL, MAVLINK_TYPE_FLOAT, 0, 16, offsetof(mavlink_kf_joint_angle_t, angle_2) }, \
         { "angle_3", NULL, MAVLINK_TYPE_FLOAT, 0, 20, offsetof(mavlink_kf_joint_angle_t, angle_3) }, \
         { "joint_id", NULL, MAVLINK_TYPE_UINT8_T, 0, 24, offsetof(mavlink_kf_joint_angle_t, joint_id) }, \
         { "sequence", NULL, MAVLINK_TYPE_UINT8_T, 0, 25, offsetof(mavlink_kf_joint_angle_t, sequence) }, \
         { "status", NULL, MAVLINK_TYPE_UINT8_T, 0, 26, offsetof(mavlink_kf_joint_angle_t, status) }, \
         { "proximal_unit", NULL, MAVLINK_TYPE_UINT8_T, 0, 27, offsetof(mavlink_kf_joint_angle_t, proximal_unit) }, \
         { "distal_unit", NULL, MAVLINK_TYPE_UINT8_T, 0, 28, offsetof(mavlink_kf_joint_angle_t, distal_unit) }, \
         } \
}
#endif

/**
 * @brief Pack a kf_joint_angle message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used (of the sending unit).
 * @param angle_1 [rad] First angle of the sequence (about the first axis, proximal frame).
 * @param angle_2 [rad] Second angle of the sequence (floating axis).
 * @param angle_3 [rad] Third angle of the sequence (about the last axis, distal frame).
 * @param joint_id  Joint.
 * @param sequence  Decomposition sequence of angle_1..3.
 * @param status  Status bits.
 * @param proximal_unit  Unit id on the proximal segment (0: not a unit).
 * @param distal_unit  Unit id on the distal segment (0: not a unit).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_joint_angle_pack(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, float angle_1, float angle_2, float angle_3, uint8_t joint_id, uint8_t sequence, uint8_t status, uint8_t proximal_unit, uint8_t distal_unit)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, angle_1);
    _mav_put_float(buf, 16, angle_2);
    _mav_put_float(buf, 20, angle_3);
    _mav_put_uint8_t(buf, 24, joint_id);
    _mav_put_uint8_t(buf, 25, sequence);
    _mav_put_uint8_t(buf, 26, status);
    _mav_put_uint8_t(buf, 27, proximal_unit);
    _mav_put_uint8_t(buf, 28, distal_unit);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#else
    mavlink_kf_joint_angle_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.angle_1 = angle_1;
    packet.angle_2 = angle_2;
    packet.angle_3 = angle_3;
    packet.joint_id = joint_id;
    packet.sequence = sequence;
    packet.status = status;
    packet.proximal_unit = proximal_unit;
    packet.distal_unit = distal_unit;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_JOINT_ANGLE;
    return mavlink_finalize_message(msg, system_id, component_id, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
}

/**
 * @brief Pack a kf_joint_angle message
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used (of the sending unit).
 * @param angle_1 [rad] First angle of the sequence (about the first axis, proximal frame).
 * @param angle_2 [rad] Second angle of the sequence (floating axis).
 * @param angle_3 [rad] Third angle of the sequence (about the last axis, distal frame).
 * @param joint_id  Joint.
 * @param sequence  Decomposition sequence of angle_1..3.
 * @param status  Status bits.
 * @param proximal_unit  Unit id on the proximal segment (0: not a unit).
 * @param distal_unit  Unit id on the distal segment (0: not a unit).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_joint_angle_pack_status(uint8_t system_id, uint8_t component_id, mavlink_status_t *_status, mavlink_message_t* msg,
                               uint64_t time_boot_us, uint32_t sample_counter, float angle_1, float angle_2, float angle_3, uint8_t joint_id, uint8_t sequence, uint8_t status, uint8_t proximal_unit, uint8_t distal_unit)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, angle_1);
    _mav_put_float(buf, 16, angle_2);
    _mav_put_float(buf, 20, angle_3);
    _mav_put_uint8_t(buf, 24, joint_id);
    _mav_put_uint8_t(buf, 25, sequence);
    _mav_put_uint8_t(buf, 26, status);
    _mav_put_uint8_t(buf, 27, proximal_unit);
    _mav_put_uint8_t(buf, 28, distal_unit);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#else
    mavlink_kf_joint_angle_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.angle_1 = angle_1;
    packet.angle_2 = angle_2;
    packet.angle_3 = angle_3;
    packet.joint_id = joint_id;
    packet.sequence = sequence;
    packet.status = status;
    packet.proximal_unit = proximal_unit;
    packet.distal_unit = distal_unit;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_JOINT_ANGLE;
#if MAVLINK_CRC_EXTRA
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
#else
    return mavlink_finalize_message_buffer(msg, system_id, component_id, _status, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#endif
}

/**
 * @brief Pack a kf_joint_angle message on a channel
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used (of the sending unit).
 * @param angle_1 [rad] First angle of the sequence (about the first axis, proximal frame).
 * @param angle_2 [rad] Second angle of the sequence (floating axis).
 * @param angle_3 [rad] Third angle of the sequence (about the last axis, distal frame).
 * @param joint_id  Joint.
 * @param sequence  Decomposition sequence of angle_1..3.
 * @param status  Status bits.
 * @param proximal_unit  Unit id on the proximal segment (0: not a unit).
 * @param distal_unit  Unit id on the distal segment (0: not a unit).
 * @return length of the message in bytes (excluding serial stream start sign)
 */
static inline uint16_t mavlink_msg_kf_joint_angle_pack_chan(uint8_t system_id, uint8_t component_id, uint8_t chan,
                               mavlink_message_t* msg,
                                   uint64_t time_boot_us,uint32_t sample_counter,float angle_1,float angle_2,float angle_3,uint8_t joint_id,uint8_t sequence,uint8_t status,uint8_t proximal_unit,uint8_t distal_unit)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, angle_1);
    _mav_put_float(buf, 16, angle_2);
    _mav_put_float(buf, 20, angle_3);
    _mav_put_uint8_t(buf, 24, joint_id);
    _mav_put_uint8_t(buf, 25, sequence);
    _mav_put_uint8_t(buf, 26, status);
    _mav_put_uint8_t(buf, 27, proximal_unit);
    _mav_put_uint8_t(buf, 28, distal_unit);

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), buf, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#else
    mavlink_kf_joint_angle_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.angle_1 = angle_1;
    packet.angle_2 = angle_2;
    packet.angle_3 = angle_3;
    packet.joint_id = joint_id;
    packet.sequence = sequence;
    packet.status = status;
    packet.proximal_unit = proximal_unit;
    packet.distal_unit = distal_unit;

        memcpy(_MAV_PAYLOAD_NON_CONST(msg), &packet, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
#endif

    msg->msgid = MAVLINK_MSG_ID_KF_JOINT_ANGLE;
    return mavlink_finalize_message_chan(msg, system_id, component_id, chan, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
}

/**
 * @brief Encode a kf_joint_angle struct
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param msg The MAVLink message to compress the data into
 * @param kf_joint_angle C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_joint_angle_encode(uint8_t system_id, uint8_t component_id, mavlink_message_t* msg, const mavlink_kf_joint_angle_t* kf_joint_angle)
{
    return mavlink_msg_kf_joint_angle_pack(system_id, component_id, msg, kf_joint_angle->time_boot_us, kf_joint_angle->sample_counter, kf_joint_angle->angle_1, kf_joint_angle->angle_2, kf_joint_angle->angle_3, kf_joint_angle->joint_id, kf_joint_angle->sequence, kf_joint_angle->status, kf_joint_angle->proximal_unit, kf_joint_angle->distal_unit);
}

/**
 * @brief Encode a kf_joint_angle struct on a channel
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param chan The MAVLink channel this message will be sent over
 * @param msg The MAVLink message to compress the data into
 * @param kf_joint_angle C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_joint_angle_encode_chan(uint8_t system_id, uint8_t component_id, uint8_t chan, mavlink_message_t* msg, const mavlink_kf_joint_angle_t* kf_joint_angle)
{
    return mavlink_msg_kf_joint_angle_pack_chan(system_id, component_id, chan, msg, kf_joint_angle->time_boot_us, kf_joint_angle->sample_counter, kf_joint_angle->angle_1, kf_joint_angle->angle_2, kf_joint_angle->angle_3, kf_joint_angle->joint_id, kf_joint_angle->sequence, kf_joint_angle->status, kf_joint_angle->proximal_unit, kf_joint_angle->distal_unit);
}

/**
 * @brief Encode a kf_joint_angle struct with provided status structure
 *
 * @param system_id ID of this system
 * @param component_id ID of this component (e.g. 200 for IMU)
 * @param status MAVLink status structure
 * @param msg The MAVLink message to compress the data into
 * @param kf_joint_angle C-struct to read the message contents from
 */
static inline uint16_t mavlink_msg_kf_joint_angle_encode_status(uint8_t system_id, uint8_t component_id, mavlink_status_t* _status, mavlink_message_t* msg, const mavlink_kf_joint_angle_t* kf_joint_angle)
{
    return mavlink_msg_kf_joint_angle_pack_status(system_id, component_id, _status, msg,  kf_joint_angle->time_boot_us, kf_joint_angle->sample_counter, kf_joint_angle->angle_1, kf_joint_angle->angle_2, kf_joint_angle->angle_3, kf_joint_angle->joint_id, kf_joint_angle->sequence, kf_joint_angle->status, kf_joint_angle->proximal_unit, kf_joint_angle->distal_unit);
}

/**
 * @brief Send a kf_joint_angle message
 * @param chan MAVLink channel to send the message
 *
 * @param time_boot_us [us] Time of the newest sample used, unit clock, microseconds since boot.
 * @param sample_counter  sample_counter of the newest sample used (of the sending unit).
 * @param angle_1 [rad] First angle of the sequence (about the first axis, proximal frame).
 * @param angle_2 [rad] Second angle of the sequence (floating axis).
 * @param angle_3 [rad] Third angle of the sequence (about the last axis, distal frame).
 * @param joint_id  Joint.
 * @param sequence  Decomposition sequence of angle_1..3.
 * @param status  Status bits.
 * @param proximal_unit  Unit id on the proximal segment (0: not a unit).
 * @param distal_unit  Unit id on the distal segment (0: not a unit).
 */
#ifdef MAVLINK_USE_CONVENIENCE_FUNCTIONS

static inline void mavlink_msg_kf_joint_angle_send(mavlink_channel_t chan, uint64_t time_boot_us, uint32_t sample_counter, float angle_1, float angle_2, float angle_3, uint8_t joint_id, uint8_t sequence, uint8_t status, uint8_t proximal_unit, uint8_t distal_unit)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char buf[MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN];
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, angle_1);
    _mav_put_float(buf, 16, angle_2);
    _mav_put_float(buf, 20, angle_3);
    _mav_put_uint8_t(buf, 24, joint_id);
    _mav_put_uint8_t(buf, 25, sequence);
    _mav_put_uint8_t(buf, 26, status);
    _mav_put_uint8_t(buf, 27, proximal_unit);
    _mav_put_uint8_t(buf, 28, distal_unit);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_JOINT_ANGLE, buf, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
#else
    mavlink_kf_joint_angle_t packet;
    packet.time_boot_us = time_boot_us;
    packet.sample_counter = sample_counter;
    packet.angle_1 = angle_1;
    packet.angle_2 = angle_2;
    packet.angle_3 = angle_3;
    packet.joint_id = joint_id;
    packet.sequence = sequence;
    packet.status = status;
    packet.proximal_unit = proximal_unit;
    packet.distal_unit = distal_unit;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_JOINT_ANGLE, (const char *)&packet, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
#endif
}

/**
 * @brief Send a kf_joint_angle message
 * @param chan MAVLink channel to send the message
 * @param struct The MAVLink struct to serialize
 */
static inline void mavlink_msg_kf_joint_angle_send_struct(mavlink_channel_t chan, const mavlink_kf_joint_angle_t* kf_joint_angle)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    mavlink_msg_kf_joint_angle_send(chan, kf_joint_angle->time_boot_us, kf_joint_angle->sample_counter, kf_joint_angle->angle_1, kf_joint_angle->angle_2, kf_joint_angle->angle_3, kf_joint_angle->joint_id, kf_joint_angle->sequence, kf_joint_angle->status, kf_joint_angle->proximal_unit, kf_joint_angle->distal_unit);
#else
    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_JOINT_ANGLE, (const char *)kf_joint_angle, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
#endif
}

#if MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN <= MAVLINK_MAX_PAYLOAD_LEN
/*
  This variant of _send() can be used to save stack space by reusing
  memory from the receive buffer.  The caller provides a
  mavlink_message_t which is the size of a full mavlink message. This
  is usually the receive buffer for the channel, and allows a reply to an
  incoming message with minimum stack space usage.
 */
static inline void mavlink_msg_kf_joint_angle_send_buf(mavlink_message_t *msgbuf, mavlink_channel_t chan,  uint64_t time_boot_us, uint32_t sample_counter, float angle_1, float angle_2, float angle_3, uint8_t joint_id, uint8_t sequence, uint8_t status, uint8_t proximal_unit, uint8_t distal_unit)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    char *buf = (char *)msgbuf;
    _mav_put_uint64_t(buf, 0, time_boot_us);
    _mav_put_uint32_t(buf, 8, sample_counter);
    _mav_put_float(buf, 12, angle_1);
    _mav_put_float(buf, 16, angle_2);
    _mav_put_float(buf, 20, angle_3);
    _mav_put_uint8_t(buf, 24, joint_id);
    _mav_put_uint8_t(buf, 25, sequence);
    _mav_put_uint8_t(buf, 26, status);
    _mav_put_uint8_t(buf, 27, proximal_unit);
    _mav_put_uint8_t(buf, 28, distal_unit);

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_JOINT_ANGLE, buf, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
#else
    mavlink_kf_joint_angle_t *packet = (mavlink_kf_joint_angle_t *)msgbuf;
    packet->time_boot_us = time_boot_us;
    packet->sample_counter = sample_counter;
    packet->angle_1 = angle_1;
    packet->angle_2 = angle_2;
    packet->angle_3 = angle_3;
    packet->joint_id = joint_id;
    packet->sequence = sequence;
    packet->status = status;
    packet->proximal_unit = proximal_unit;
    packet->distal_unit = distal_unit;

    _mav_finalize_message_chan_send(chan, MAVLINK_MSG_ID_KF_JOINT_ANGLE, (const char *)packet, MAVLINK_MSG_ID_KF_JOINT_ANGLE_MIN_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN, MAVLINK_MSG_ID_KF_JOINT_ANGLE_CRC);
#endif
}
#endif

#endif

// MESSAGE KF_JOINT_ANGLE UNPACKING


/**
 * @brief Get field time_boot_us from kf_joint_angle message
 *
 * @return [us] Time of the newest sample used, unit clock, microseconds since boot.
 */
static inline uint64_t mavlink_msg_kf_joint_angle_get_time_boot_us(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint64_t(msg,  0);
}

/**
 * @brief Get field sample_counter from kf_joint_angle message
 *
 * @return  sample_counter of the newest sample used (of the sending unit).
 */
static inline uint32_t mavlink_msg_kf_joint_angle_get_sample_counter(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint32_t(msg,  8);
}

/**
 * @brief Get field angle_1 from kf_joint_angle message
 *
 * @return [rad] First angle of the sequence (about the first axis, proximal frame).
 */
static inline float mavlink_msg_kf_joint_angle_get_angle_1(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  12);
}

/**
 * @brief Get field angle_2 from kf_joint_angle message
 *
 * @return [rad] Second angle of the sequence (floating axis).
 */
static inline float mavlink_msg_kf_joint_angle_get_angle_2(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  16);
}

/**
 * @brief Get field angle_3 from kf_joint_angle message
 *
 * @return [rad] Third angle of the sequence (about the last axis, distal frame).
 */
static inline float mavlink_msg_kf_joint_angle_get_angle_3(const mavlink_message_t* msg)
{
    return _MAV_RETURN_float(msg,  20);
}

/**
 * @brief Get field joint_id from kf_joint_angle message
 *
 * @return  Joint.
 */
static inline uint8_t mavlink_msg_kf_joint_angle_get_joint_id(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  24);
}

/**
 * @brief Get field sequence from kf_joint_angle message
 *
 * @return  Decomposition sequence of angle_1..3.
 */
static inline uint8_t mavlink_msg_kf_joint_angle_get_sequence(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  25);
}

/**
 * @brief Get field status from kf_joint_angle message
 *
 * @return  Status bits.
 */
static inline uint8_t mavlink_msg_kf_joint_angle_get_status(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  26);
}

/**
 * @brief Get field proximal_unit from kf_joint_angle message
 *
 * @return  Unit id on the proximal segment (0: not a unit).
 */
static inline uint8_t mavlink_msg_kf_joint_angle_get_proximal_unit(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  27);
}

/**
 * @brief Get field distal_unit from kf_joint_angle message
 *
 * @return  Unit id on the distal segment (0: not a unit).
 */
static inline uint8_t mavlink_msg_kf_joint_angle_get_distal_unit(const mavlink_message_t* msg)
{
    return _MAV_RETURN_uint8_t(msg,  28);
}

/**
 * @brief Decode a kf_joint_angle message into a struct
 *
 * @param msg The message to decode
 * @param kf_joint_angle C-struct to decode the message contents into
 */
static inline void mavlink_msg_kf_joint_angle_decode(const mavlink_message_t* msg, mavlink_kf_joint_angle_t* kf_joint_angle)
{
#if MAVLINK_NEED_BYTE_SWAP || !MAVLINK_ALIGNED_FIELDS
    kf_joint_angle->time_boot_us = mavlink_msg_kf_joint_angle_get_time_boot_us(msg);
    kf_joint_angle->sample_counter = mavlink_msg_kf_joint_angle_get_sample_counter(msg);
    kf_joint_angle->angle_1 = mavlink_msg_kf_joint_angle_get_angle_1(msg);
    kf_joint_angle->angle_2 = mavlink_msg_kf_joint_angle_get_angle_2(msg);
    kf_joint_angle->angle_3 = mavlink_msg_kf_joint_angle_get_angle_3(msg);
    kf_joint_angle->joint_id = mavlink_msg_kf_joint_angle_get_joint_id(msg);
    kf_joint_angle->sequence = mavlink_msg_kf_joint_angle_get_sequence(msg);
    kf_joint_angle->status = mavlink_msg_kf_joint_angle_get_status(msg);
    kf_joint_angle->proximal_unit = mavlink_msg_kf_joint_angle_get_proximal_unit(msg);
    kf_joint_angle->distal_unit = mavlink_msg_kf_joint_angle_get_distal_unit(msg);
#else
        uint8_t len = msg->len < MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN? msg->len : MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN;
        memset(kf_joint_angle, 0, MAVLINK_MSG_ID_KF_JOINT_ANGLE_LEN);
    memcpy(kf_joint_angle, _MAV_PAYLOAD(msg), len);
#endif
}
