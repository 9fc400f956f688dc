; socket: slide the peg into a socket 4 mm wider than it. Expected: 2 actions.
(define (problem robust-socket)
  (:domain robust-planar)
  (:objects peg - block
            table socket - region)
  (:init (in peg table) (handempty))
  (:goal (in peg socket)))
