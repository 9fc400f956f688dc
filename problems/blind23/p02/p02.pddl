; blind23 p02: a 10 x 10 x 6 cm crate (too wide for the KUKA's 7.5 cm grip)
; must go from `home` to `dock`, 20 cm along +x and 20 cm along +y: 45 deg
; off every face's normal, outside the 26.6 deg friction cone, so no single
; push can do it. Two pushes from different faces, through `mid-a` (x first)
; or `mid-b` (y first).
; Cheapest (cost 2): (push crate home dock) or (pick crate home) (place crate dock)
; Expected (cost 4): (push crate home mid-a) (push crate mid-a dock)  [or via mid-b]
(define (problem p02)
  (:domain crate-two-pushes)
  (:objects crate - thing
            home mid-a mid-b dock - zone)
  (:init (at crate home) (handempty) (= (total-cost) 0))
  (:goal (at crate dock))
  (:metric minimize (total-cost)))
