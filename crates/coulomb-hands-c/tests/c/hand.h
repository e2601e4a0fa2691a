/* A tracked hand for the C tests: 26 OpenXR joints (XrHandJointEXT order, metres, y up)
 * of a hand, palm down, whose straight index finger points along x at a box and presses its
 * tip into one face; the other fingers hang down below their knuckles and the thumb lies
 * beside the palm, far from the box. Two such hands, one each side, pinch the box between
 * their index fingertips. */
#ifndef HAND_H
#define HAND_H

#include <stddef.h>

#define JOINTS 26

static void put(float *joints, int j, const float at[3], float f, float down, float lateral) {
  /* at + f along the finger's direction (x, signed by the caller), down below, lateral in z */
  joints[3 * j + 0] = at[0] + f;
  joints[3 * j + 1] = at[1] - down;
  joints[3 * j + 2] = at[2] + lateral;
}

/* side: -1 for the hand on the box's -x side (a left hand), +1 for the +x side (a right
 * hand). tip_x: where the index fingertip's joint is (m); y, z: the box's height and depth. */
static void pinch_hand(int side, float tip_x, float y, float z, float joints[3 * JOINTS],
                       float radii[JOINTS]) {
  const float dir = (float)-side; /* the fingers point at the box */
  const float tip[3] = {tip_x, y, z};
  float wrist[3] = {tip_x - dir * 0.165f, y, z};
  put(joints, 0, wrist, dir * 0.085f, 0.0f, -0.03f);  /* palm */
  put(joints, 1, wrist, 0.0f, 0.0f, -0.02f);          /* wrist */
  put(joints, 2, wrist, dir * 0.02f, 0.0f, 0.02f);    /* thumb metacarpal */
  put(joints, 3, wrist, dir * 0.05f, 0.0f, 0.04f);    /* thumb proximal */
  put(joints, 4, wrist, dir * 0.08f, 0.0f, 0.055f);   /* thumb distal */
  put(joints, 5, wrist, dir * 0.10f, 0.0f, 0.065f);   /* thumb tip */
  put(joints, 6, wrist, dir * 0.01f, 0.0f, 0.0f);     /* index metacarpal */
  put(joints, 7, tip, -dir * 0.085f, 0.0f, 0.0f);     /* index proximal (knuckle) */
  put(joints, 8, tip, -dir * 0.045f, 0.0f, 0.0f);     /* index intermediate */
  put(joints, 9, tip, -dir * 0.022f, 0.0f, 0.0f);     /* index distal */
  put(joints, 10, tip, 0.0f, 0.0f, 0.0f);             /* index tip */
  for (int k = 1; k <= 3; k++) {                      /* middle, ring, little: hanging */
    const int base = 6 + 5 * k;
    const float lateral = -0.021f * (float)k;
    put(joints, base, wrist, dir * 0.01f, 0.0f, lateral);
    put(joints, base + 1, tip, -dir * 0.085f, 0.0f, lateral);
    put(joints, base + 2, tip, -dir * 0.085f, 0.035f, lateral);
    put(joints, base + 3, tip, -dir * 0.085f, 0.06f, lateral);
    put(joints, base + 4, tip, -dir * 0.085f, 0.08f, lateral);
  }
  for (int j = 0; j < JOINTS; j++) radii[j] = j < 2 ? 0.0f : 0.008f;
}

#endif
