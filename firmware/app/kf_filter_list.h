/*
 * kf_filter_list.h - the orientation filters wired into the application, one line each.
 *
 *     KF_FILTER_ENTRY(name, id, tag)
 *
 * name: a generated IMU filter (firmware/generated/<name>_f32.[ch] and <name>_q.[ch]);
 * id:   its value of the parameter KF_FILTER and of KF_ORIENTATION.filter_id (MAVLink enum
 *       KF_FILTER; values >= 8 are kinefuse additions not yet in kinefuse.xml);
 * tag:  two letters naming its MAVLink parameters, KF_<tag>_<PARAM> (16 characters at most).
 *
 * After adding a line run `python -m kinefuse.firmware.build tables` (it regenerates
 * kf_filters_gen.[ch] and kf_params_gen.inc from the generated filters' models).  The f32
 * builds link <name>_f32, the fixed-point (M0) build links <name>_q.
 */
KF_FILTER_ENTRY(complementary, 2, CF)
KF_FILTER_ENTRY(madgwick, 3, MW)
KF_FILTER_ENTRY(mahony, 4, MH)
KF_FILTER_ENTRY(flagship, 5, FL)
KF_FILTER_ENTRY(eskf, 6, EK)
KF_FILTER_ENTRY(ecompass, 8, EC)
KF_FILTER_ENTRY(triad, 9, TR)
KF_FILTER_ENTRY(vac, 10, VC)
KF_FILTER_ENTRY(vak, 11, VK)
KF_FILTER_ENTRY(guo, 12, GU)
