#!/usr/bin/env bash
# `granshock collide --model hooke`: a steel-aluminium impact at 5 m/s with the
# characteristic velocity 1 m/s and e = 0.9 must report the hooke law, the closed-form
# contact time t_c = pi / omega_d of the stiffness chosen at 1 m/s (not at 5 m/s),
# e_eff = e and t_contact = t_c within velocity Verlet's first-order error at
# dt = t_c/100 (the bounds derived in tests/physics/test_hooke_contact.cpp). The law is
# computed here from the material data and LIGGGHTS' formulas, independently of the code.
# Usage: collide_hooke.sh GRANSHOCK
set -u
out=$("$1" collide --model hooke --pair steel-aluminium --speed 5 --characteristic-velocity 1 \
  --e 0.9 2>/dev/null) || { echo "collide failed"; exit 1; }
value() { printf '%s\n' "$out" | sed -n "s/^ *\"$1\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p"; }
model=$(value model) e_eff=$(value e_eff) t_c=$(value t_c) t_contact=$(value t_contact) dt=$(value dt)
[ "$model" = hooke ] || { echo "model is '$model', not hooke:"; echo "$out"; exit 1; }
awk -v e_eff="$e_eff" -v t_c="$t_c" -v t_contact="$t_contact" -v dt="$dt" 'BEGIN {
  pi = atan2(0, -1); e = 0.9; V = 1.0; d = 1e-3; r = d / 2
  m_steel = 7850 * pi * d^3 / 6; m_al = m_steel / 2.907
  Y = 1 / ((1 - 0.303^2) / 210e9 + (1 - 0.33^2) / 69e9); R = r / 2
  m = m_steel * m_al / (m_steel + m_al)
  kn = 16 / 15 * sqrt(R) * Y * (15 * m * V^2 / (16 * sqrt(R) * Y))^0.2
  gn = sqrt(4 * m * kn / (1 + (pi / log(e))^2))
  w0 = sqrt(kn / m); z = gn / (2 * sqrt(m * kn)); tc = pi / sqrt(kn / m - (gn / (2 * m))^2)
  h = w0 * dt; c = z * h
  e_tol = (2 + pi * z / (2 * (1 - z^2)^1.5)) * c + h^2
  t_pred = tc * (1 - c * (1 - 2 * z^2) / (2 * (1 - z^2)) - h^2 / 24)
  printf "t_c %.6g s (closed form %.6g s), e_eff %.5f (bound %.3f %%), t_contact / t_c %.5f\n",
    t_c, tc, e_eff, 100 * e_tol, t_contact / tc
  status = 0
  if ((t_c / tc - 1)^2 > 1e-18) { print "t_c is not pi / omega_d at V = 1 m/s"; status = 1 }
  if ((e_eff / e - 1)^2 > e_tol^2) { print "e_eff is not e"; status = 1 }
  if ((t_contact / t_pred - 1)^2 > 1e-8) { print "t_contact is not pi / omega_d"; status = 1 }
  exit status
}'
