# The elements of examples/mca-shock's inputs (in.plate, in.disc): the metal of a material card
# potentials/NAME.shock read, then the neighbour skin, the elements' size, pair_style mca with
# the shock equation of state, the yield stress and the fracture, the density and the time step
# theta d / c_L.  Included once the atoms exist; the variables it reads (metal, d, theta,
# strength, fracture, yield, extra, here, cards) are the including input's, as documented there.
variable card     string ${cards}/${metal}.shock
variable found    equal is_file(${card})
if "${found} == 0" then &
  "print 'ERROR: no material card ${card} (-var metal ${metal}): the cards are potentials/*.shock, listed in potentials/README.md; from another folder give -var here <examples/mca-shock>/'" &
  "quit 1"
include      ${card}
if "$(0.5*v_v) > ${upmax}" then &
  "print 'WARNING: impact at ${v} m/s: up = v/2 is beyond the range of the card ${metal} (${material}: up to ${upmax} m/s, its header)'"
if "${strength} > 0" then "variable spall equal ${strength}"
if "${yield} >= 0" then "variable Y equal ${yield}"
# skin: 0.25 d; with yield 0.6 d: a yielding link stretches plastically beyond its contact
# before the tension breaks it, and must stay in the list (an error otherwise), as
# examples/mca-spall/in.plate
neighbor     $((0.25+0.35*(v_Y>0))*v_d) bin
neigh_modify every 1 delay 0 check yes
set          group all diameter ${d}
variable     phi equal PI/sqrt(18.0)
variable     plastic string ""
if "${Y} > 0" then "variable plastic string 'yield ${Y}'"
pair_style   mca fraction ${phi} tolerance 0.02
variable     breaking string "spall ${spall} ${spall_rate} ${spall_m}"
if "${fracture} == threshold" then "variable breaking string 'strength ${spall}'" &
  elif "${fracture} == pressure" "variable breaking string 'spall ${spall} 1.0e6 0.01'" &
  elif "${fracture} != kinetics" &
  "print 'ERROR: -var fracture ${fracture}: give kinetics (spall kinetics of the elements), threshold (strength of the links) or pressure (a mean-tension threshold)'" "quit 1"
pair_coeff   1 1 shock ${rho} ${c0} ${s} ${gamma} shear ${G} ${plastic} ${breaking} ${extra}
set          group all density $(v_rho/v_phi)
timestep     $(v_theta*v_d/v_cL)
