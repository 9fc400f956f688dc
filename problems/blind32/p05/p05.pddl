; Assemble base + peg + cap at the jig. Expected, 7 actions:
; (pick base base-bin) (seat base) (pick peg peg-bin) (mount-peg peg base)
; (fasten peg base) (pick cap cap-bin) (cap cap peg).
; The order is fixed: the cap needs a fastened peg, and fasten needs the
; hand empty, so the cap is picked only after the fasten.
(define (problem assemble-one)
  (:domain jig-assembly)
  (:objects base - plate  peg - peg  cap - cap
            base-bin peg-bin cap-bin - zone)
  (:init (at base base-bin) (at peg peg-bin) (at cap cap-bin)
         (clear base) (clear peg) (clear cap) (handempty))
  (:goal (and (assembled base) (handempty))))
